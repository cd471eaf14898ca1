//ICE::Dec
in vec3 iceNormalMC;
uniform mat4 iceMCWCMatrix;       // model (VBO shift/scale included) to world
uniform mat3 iceNormalMCWCMatrix; // model to world for normals
uniform vec3 iceCameraWC;
out vec3 icePositionWC;
out vec3 iceNormalWC;
//ICE::Impl
  icePositionWC = (iceMCWCMatrix * vertexMC).xyz;
  iceNormalWC = iceNormalMCWCMatrix * iceNormalMC;
