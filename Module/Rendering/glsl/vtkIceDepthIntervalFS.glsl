// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Normal
// The front faces' world normal in the target's B and A: a unit vector in two floats, folded onto
// the octahedron |x| + |y| + |z| = 1 (the lower half over the upper's corners). A is offset by 2:
// VTK's fragment shader discards what it leaves with an alpha of 0 or less.
vec2 iceEncodeNormal(vec3 n)
{
  vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
  vec2 signs = vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
  return (n.z >= 0.0 ? p : (1.0 - abs(p.yx)) * signs) + vec2(0.0, 2.0);
}
vec3 iceDecodeNormal(vec2 stored)
{
  vec2 p = stored - vec2(0.0, 2.0);
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  float fold = max(-n.z, 0.0);
  n.xy -= vec2(n.x >= 0.0 ? fold : -fold, n.y >= 0.0 ? fold : -fold);
  return normalize(n);
}
//ICE::Dec
uniform int iceDepthStage; // 0: front faces, 1: back faces
//ICE::Impl
  // Front faces in the first stage (their view depth in R, their normal in B and A), back faces
  // in the second (their view depth in G).
  if (gl_FrontFacing != (iceDepthStage == 0)) { discard; }
  gl_FragData[0] = vec4(iceViewDepth(), iceViewDepth(),
    iceEncodeNormal(normalize(iceNormalWCVSOutput)));
