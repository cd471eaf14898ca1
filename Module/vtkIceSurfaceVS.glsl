//ICE::Dec
uniform float iceFresnelPower;
out float iceFresnelFactor;
//ICE::Impl
  iceFresnelFactor = iceFresnel(normalize(icePositionWC - iceCameraWC), normalize(iceNormalWC),
    iceFresnelPower);
