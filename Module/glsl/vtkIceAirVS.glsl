//ICE::Dec
in vec2 iceAirUVMC;
out vec2 iceAirUVVSOutput;
//ICE::Impl
  iceAirUVVSOutput = iceAirUVMC;
