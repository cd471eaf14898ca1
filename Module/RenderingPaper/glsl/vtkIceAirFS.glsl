// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
in vec2 iceAirUVVSOutput;
uniform sampler2D iceAirAtlas;      // bubble images (RGBA)
uniform sampler2D iceDepthInterval; // front (R) and back (G) view depth of the ice
uniform float iceMilkiness;         // 0: sparse clear bubbles, 1: white and cloudy
uniform int iceAirDebug;            // 1: solid green where a bubble covers
//ICE::Impl
  {
    vec2 interval = texelFetch(iceDepthInterval, iceScreenTexel(), 0).rg;
    float depth = iceViewDepth();
    if (depth < interval.x || depth > interval.y) { discard; }
    vec4 layer = iceAirLayer(texture(iceAirAtlas, iceAirUVVSOutput), iceMilkiness, iceAirDebug == 1);
    if (iceAirDebug == 1 && layer.a == 0.0) { discard; }
    gl_FragData[0] = layer;
    // Seen where the ice's front surface is seen (see the crack shader).
    gl_FragDepth = iceWindowDepth(interval.x * 0.99);
  }
