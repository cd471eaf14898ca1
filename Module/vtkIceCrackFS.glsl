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

float iceValueNoise(vec3 x)
{
  vec3 i = floor(x);
  vec3 f = fract(x);
  f = f * f * (3.0 - 2.0 * f);
  float a = mix(iceHash(i), iceHash(i + vec3(1, 0, 0)), f.x);
  float b = mix(iceHash(i + vec3(0, 1, 0)), iceHash(i + vec3(1, 1, 0)), f.x);
  float c = mix(iceHash(i + vec3(0, 0, 1)), iceHash(i + vec3(1, 0, 1)), f.x);
  float d = mix(iceHash(i + vec3(0, 1, 1)), iceHash(i + vec3(1, 1, 1)), f.x);
  return mix(mix(a, b, f.y), mix(c, d, f.y), f.z);
}

// Window depth of a view depth for the current camera.
float iceWindowDepth(float viewDepth)
{
  float ndc = iceDepthToWindow.z > 0.5 ? -iceDepthToWindow.x * viewDepth + iceDepthToWindow.y
                                        : (iceDepthToWindow.y - iceDepthToWindow.x * viewDepth) / viewDepth;
  return 0.5 * ndc + 0.5;
}
//ICE::Normal
  {
    // Bump mapping: tilt the normal by the gradient of a noise field fixed to the crack.
    vec3 p = iceCrackMC * iceBumpFrequency;
    const float h = 0.05;
    vec3 gradient = vec3(
      iceValueNoise(p + vec3(h, 0, 0)) - iceValueNoise(p - vec3(h, 0, 0)),
      iceValueNoise(p + vec3(0, h, 0)) - iceValueNoise(p - vec3(0, h, 0)),
      iceValueNoise(p + vec3(0, 0, h)) - iceValueNoise(p - vec3(0, 0, h))) / (2.0 * h);
    vec3 gradientVC = normalMatrix * gradient;
    gradientVC -= dot(gradientVC, normalVCVSOutput) * normalVCVSOutput;
    normalVCVSOutput = normalize(normalVCVSOutput - iceBumpStrength * gradientVC);
  }
//ICE::Impl
  {
    vec2 interval = texelFetch(iceDepthInterval, iceScreenTexel(), 0).rg;
    float depth = iceViewDepth();
    if (iceCrackClip == 1 && (depth < interval.x || depth > interval.y)) { discard; }
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
