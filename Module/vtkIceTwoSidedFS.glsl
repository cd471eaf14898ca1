//ICE::Dec
uniform sampler2D iceBackNormals; // world-space back-face normals; alpha 0 where no ice
uniform ivec2 iceViewportOrigin;  // window position of texel (0, 0)
uniform float iceBackNormalWeight;
//ICE::Impl
    vec4 back = texelFetch(iceBackNormals, ivec2(gl_FragCoord.xy) - iceViewportOrigin, 0);
    if (back.a > 0.0)
    {
      nRefract = iceBlendNormals(nFront, back.xyz, iceBackNormalWeight);
    }
