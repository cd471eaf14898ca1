//ICE::Dec
in vec2 iceAirUVMC;
out vec2 iceAirUV;
//ICE::Impl
  iceAirUV = iceAirUVMC;
