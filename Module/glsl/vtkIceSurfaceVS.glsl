//ICE::Dec
uniform float iceFresnelPower;
out float iceFresnelFactorVSOutput;
//ICE::Impl
  iceFresnelFactorVSOutput = iceFresnel(iceEyeVectorWC(icePositionWCVSOutput), normalize(iceNormalWCVSOutput),
    iceFresnelPower);
