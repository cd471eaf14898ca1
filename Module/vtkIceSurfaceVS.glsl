//ICE::Dec
uniform float iceFresnelPower;
out float iceFresnelFactor;
//ICE::Impl
  iceFresnelFactor = iceFresnel(iceEyeVectorWC(icePositionWC), normalize(iceNormalWC),
    iceFresnelPower);
