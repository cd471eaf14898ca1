//ICE::Dec
uniform sampler2D iceBackNormals; // world-space back-face normals; alpha 0 where no ice
uniform float iceBackNormalWeight;
//ICE::Impl
    vec4 back = texelFetch(iceBackNormals, iceScreenTexel(), 0);
    if (back.a > 0.0)
    {
      nRefract = iceBlendNormals(nFront, back.xyz, iceBackNormalWeight);
    }
