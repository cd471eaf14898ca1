//ICE::Dec
out vec3 iceCrackMC;
//ICE::Impl
  iceCrackMC = vertexMC.xyz;
