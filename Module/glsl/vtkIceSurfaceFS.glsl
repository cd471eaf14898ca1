//ICE::Dec
in float iceFresnelFactorVSOutput;
uniform samplerCube iceEnvironment;
uniform float iceRefractionRatio;
uniform vec3 iceTint;
//ICE::Impl
  {
    vec3 e = iceEyeVectorWC(icePositionWCVSOutput);
    vec3 nFront = normalize(iceNormalWCVSOutput);
    if (gl_FrontFacing == false) { nFront = -nFront; }
    float fresnel = iceFresnelFactorVSOutput;
    //ICEHOOK::SurfaceNormal
    vec3 nRefract = nFront;
    //ICEHOOK::RefractionNormal
    vec3 refractedDirection = iceRefract(e, nRefract, iceRefractionRatio);
    //ICEHOOK::RefractionDirection
    vec3 refracted = texture(iceEnvironment, refractedDirection).rgb;
    vec3 reflected = texture(iceEnvironment, iceReflect(e, nFront)).rgb;
    gl_FragData[0].rgb = iceTint * mix(refracted, reflected, clamp(fresnel, 0.0, 1.0));
    //ICEHOOK::Interior
    //ICEHOOK::Glistening
    //ICEHOOK::Debug
    //ICEHOOK::Edges
  }
  //ICEHOOK::Output
