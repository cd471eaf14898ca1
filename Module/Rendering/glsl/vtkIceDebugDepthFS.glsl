// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
uniform sampler2D iceDepthInterval; // front (R) and back (G) view depth of the ice
uniform vec2 iceDepthRange;         // view depths shown as black and white
uniform int iceDebugChannel;        // 0: front depth, 1: back depth
//ICE::Impl
    {
      vec2 interval = texelFetch(iceDepthInterval, iceScreenTexel(), 0).rg;
      float depth = iceDebugChannel == 0 ? interval.x : interval.y;
      float range = max(iceDepthRange.y - iceDepthRange.x, 1e-6);
      gl_FragData[0].rgb = vec3(clamp((depth - iceDepthRange.x) / range, 0.0, 1.0));
    }
