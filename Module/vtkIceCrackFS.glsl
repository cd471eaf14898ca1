//ICE::Dec
in vec3 iceCrackMC;
uniform sampler2D iceDepthInterval; // front (R) and back (G) view depth of the ice
uniform int iceCrackClip;           // 1: discard outside the ice's depth interval
uniform int iceCrackDebug;          // 1: solid red, as in the paper's Figure 5
uniform float iceCrackIntensity;
uniform float iceBumpStrength;
uniform float iceBumpFrequency;
uniform vec4 iceDepthToWindow;      // projection P22, P23, parallel (0/1), unused

float iceHash(vec3 p)
{
  p = fract(p * 0.1031 + vec3(0.13, 0.71, 0.37));
  p += dot(p, p.yzx + 19.19);
  return fract((p.x + p.y) * p.z);
}

// Value noise: the eight hashed lattice values around x blended with smoothstep weights.
// Returns the gradient of that field, exactly (the derivative of the blend): one set of eight
// hashes per fragment instead of six noise evaluations for central differences.
vec3 iceValueNoiseGradient(vec3 x)
{
  vec3 i = floor(x);
  vec3 f = fract(x);
  vec3 u = f * f * (3.0 - 2.0 * f);
  vec3 du = 6.0 * f * (1.0 - f);
  float k000 = iceHash(i);
  float k100 = iceHash(i + vec3(1, 0, 0));
  float k010 = iceHash(i + vec3(0, 1, 0));
  float k110 = iceHash(i + vec3(1, 1, 0));
  float k001 = iceHash(i + vec3(0, 0, 1));
  float k101 = iceHash(i + vec3(1, 0, 1));
  float k011 = iceHash(i + vec3(0, 1, 1));
  float k111 = iceHash(i + vec3(1, 1, 1));
  float bxy = k000 - k100 - k010 + k110;
  float bxz = k000 - k100 - k001 + k101;
  float byz = k000 - k010 - k001 + k011;
  float bxyz = -k000 + k100 + k010 - k110 + k001 - k101 - k011 + k111;
  return du * vec3(k100 - k000 + bxy * u.y + bxz * u.z + bxyz * u.y * u.z,
                   k010 - k000 + bxy * u.x + byz * u.z + bxyz * u.x * u.z,
                   k001 - k000 + bxz * u.x + byz * u.y + bxyz * u.x * u.y);
}

// Window depth of a view depth for the current camera.
float iceWindowDepth(float viewDepth)
{
  float ndc = iceDepthToWindow.z > 0.5 ? -iceDepthToWindow.x * viewDepth + iceDepthToWindow.y
                                        : (iceDepthToWindow.y - iceDepthToWindow.x * viewDepth) / viewDepth;
  return 0.5 * ndc + 0.5;
}
//ICE::Interval
  // The ice's depth interval here; outside it nothing is drawn, so leave before the bump mapping.
  vec2 iceInterval = texelFetch(iceDepthInterval, iceScreenTexel(), 0).rg;
  if (iceCrackClip == 1 && (iceViewDepth() < iceInterval.x || iceViewDepth() > iceInterval.y))
  {
    discard;
  }
//ICE::Normal
  {
    // Bump mapping: tilt the normal by the gradient of a noise field fixed to the crack.
    vec3 gradientVC = normalMatrix * iceValueNoiseGradient(iceCrackMC * iceBumpFrequency);
    gradientVC -= dot(gradientVC, normalVCVSOutput) * normalVCVSOutput;
    normalVCVSOutput = normalize(normalVCVSOutput - iceBumpStrength * gradientVC);
  }
//ICE::Impl
  {
    vec2 interval = iceInterval;
    // Only the specular highlight shows; where there is none the crack adds nothing.
    gl_FragData[0] = iceCrackDebug == 1 ? vec4(1.0, 0.0, 0.0, 1.0)
                                        : vec4(iceCrackIntensity * gl_FragData[0].rgb, 1.0);
    // A crack is seen where the ice's front surface is seen: test it at the ice's front depth,
    // 1 % closer (more than the surface's depth change across a pixel's multisamples), so what
    // occludes the ice occludes its cracks.
    bool iceHere = interval.x <= interval.y;
    gl_FragDepth = iceHere ? iceWindowDepth(interval.x * 0.99) : gl_FragCoord.z;
  }
  //ICEHOOK::CrackOutput
