// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
// VTK draws edges by growing each triangle in its geometry shader by half a line width on the
// screen, with the varyings of the original corners: inside the triangle they are then
// stretched (bubbles and cracks moved by up to 15/255 in the interior then drawn in the surface). The ice instead puts
// each grown corner on the triangle's plane and gives it the triangle's values there: weights
// of the three corners for the grown corner i at `offset` (normalised device coordinates).
bool iceGrownCornerWeights(int i, vec2 offset, out vec3 weights)
{
  weights = vec3(float(i == 0), float(i == 1), float(i == 2));
  vec4 p0 = gl_in[0].gl_Position;
  vec4 p1 = gl_in[1].gl_Position;
  vec4 p2 = gl_in[2].gl_Position;
  if (p0.w <= 0.0 || p1.w <= 0.0 || p2.w <= 0.0)
  {
    return false; // crosses the camera plane: VTK's corners
  }
  vec2 n0 = p0.xy / p0.w;
  vec2 a = p1.xy / p1.w - n0;
  vec2 b = p2.xy / p2.w - n0;
  vec2 c = gl_in[i].gl_Position.xy / gl_in[i].gl_Position.w + offset - n0;
  float area = a.x * b.y - b.x * a.y;
  if (abs(area) < 1.0e-12)
  {
    return false;
  }
  float l1 = (c.x * b.y - b.x * c.y) / area;
  float l2 = (a.x * c.y - c.x * a.y) / area;
  // Screen weights to homogeneous ones: the point of the plane that projects there.
  vec3 h = vec3(1.0 - l1 - l2, l1, l2) / vec3(p0.w, p1.w, p2.w);
  weights = h / (h.x + h.y + h.z);
  return true;
}
//ICE::Impl
    vec3 iceWeights;
    bool iceOnPlane = iceGrownCornerWeights(i, offsets[i], iceWeights);
//ICE::Position
    if (iceOnPlane)
    {
      gl_Position = iceWeights.x * gl_in[0].gl_Position + iceWeights.y * gl_in[1].gl_Position +
        iceWeights.z * gl_in[2].gl_Position;
    }
