//ICE::Dec
uniform float iceBackNormalWeight;
//ICE::Impl
    vec4 back = texelFetch(iceBackNormals, iceScreenTexel(), 0);
    if (back.a > 0.0)
    {
      nRefract = iceBlendNormals(nFront, back.xyz, iceBackNormalWeight);
    }
