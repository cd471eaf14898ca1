// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
uniform sampler2D iceNormalMap; // tangent-space normals, RGB in [0, 1]
uniform float iceBumpStrength;
uniform float iceBumpFrequency; // map repeats per model unit
uniform float iceFresnelPower;
//ICE::Impl
    {
      // The map projected on the three model planes (no texture coordinates needed), each
      // tilting the model normal within its plane, blended by how much the normal faces it.
      vec3 n = normalize(iceNormalModelVSOutput);
      vec3 p = icePositionMCVSOutput * iceBumpFrequency;
      vec2 tx = (texture(iceNormalMap, p.zy).xy * 2.0 - 1.0) * iceBumpStrength;
      vec2 ty = (texture(iceNormalMap, p.xz).xy * 2.0 - 1.0) * iceBumpStrength;
      vec2 tz = (texture(iceNormalMap, p.xy).xy * 2.0 - 1.0) * iceBumpStrength;
      vec3 w = abs(n) / max(dot(abs(n), vec3(1.0)), 1e-6);
      vec3 tilted = normalize(w.x * vec3(n.x, n.y + tx.y, n.z + tx.x) +
        w.y * vec3(n.x + ty.x, n.y, n.z + ty.y) + w.z * vec3(n.x + tz.x, n.y + tz.y, n.z));
      vec3 tiltedWC = normalize(iceNormalMCWCMatrix * tilted);
      nFront = gl_FrontFacing ? tiltedWC : -tiltedWC;
      fresnel = iceFresnel(e, nFront, iceFresnelPower);
    }
