// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
uniform sampler2D iceDepthInterval; // front (R) and back (G) view depth of the ice
uniform int iceCrackClip;           // 1: discard outside the ice's depth interval
uniform int iceCrackDebug;          // 1: solid red, as in the paper's Figure 5
uniform float iceCrackIntensity;
uniform float iceBumpStrength;
uniform float iceBumpFrequency;

//ICE::Interval
  // The ice's depth interval here; outside it nothing is drawn, so leave before the bump mapping.
  vec2 iceInterval = texelFetch(iceDepthInterval, iceScreenTexel(), 0).rg;
  if (iceCrackClip == 1 && (iceViewDepth() < iceInterval.x || iceViewDepth() > iceInterval.y))
  {
    discard;
  }
//ICE::Normal
  {
    // Bump mapping: tilt the normal by the gradient of a noise field fixed to the crack (in true
    // model coordinates, VTK's shift/scale of the vertex buffer undone).
    vec3 gradientVC = normalMatrix * iceNoiseGradient(icePositionMCVSOutput * iceBumpFrequency);
    normalVCVSOutput = iceBumpNormal(normalVCVSOutput, gradientVC, iceBumpStrength);
  }
//ICE::Impl
  {
    vec2 interval = iceInterval;
    // Only the specular highlight shows; where there is none the crack adds nothing.
    gl_FragData[0] = iceCrackDebug == 1 ? vec4(1.0, 0.0, 0.0, 1.0)
                                        : vec4(iceCrackIntensity * gl_FragData[0].rgb, 1.0);
    // A crack is seen where the ice's front surface is seen: test it at the ice's front depth,
    // 1 % closer (more than the surface's depth change across a pixel's multisamples), so what
    // occludes the ice occludes its cracks.
    bool iceHere = interval.x <= interval.y;
    gl_FragDepth = iceHere ? iceWindowDepth(interval.x * 0.99) : gl_FragCoord.z;
  }
  //ICEHOOK::CrackOutput
