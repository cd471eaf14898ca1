// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
uniform float iceBackNormalWeight;
//ICE::Impl
    vec4 back = texelFetch(iceBackNormals, iceScreenTexel(), 0);
    if (back.a > 0.0)
    {
      nRefract = iceBlendNormals(nFront, back.xyz, iceBackNormalWeight);
    }
