//ICE::SurfaceDec
// The interior vtkIceScreenInterior evaluated for this pixel, as vec4(add, keep).
uniform sampler2D iceScreenInterior;
//ICE::SurfaceCall
    if (gl_FrontFacing)
    {
      vec4 iceScreenInteriorResult = texelFetch(iceScreenInterior, iceScreenTexel(), 0);
      gl_FragData[0].rgb =
        gl_FragData[0].rgb * iceScreenInteriorResult.a + iceScreenInteriorResult.rgb;
    }
//ICE::Dec
// The screen-space interior (vtkIceScreenInterior): one ice prop's interior once per pixel, from
// its own nearest front face (the view depth in the depth interval's R; FLT_MAX: none) to the
// nearest back face of the ice (the back-face target's alpha), as the single pass evaluates it
// per fragment; written as vec4(add, keep) at the front face's window depth, so that where ice
// props overlap the nearest one's interior stays.
uniform sampler2D iceDepthInterval;
uniform sampler2D iceBackNormals;
uniform mat4 iceDCWCMatrix; // normalised device coordinates to world
//ICE::Impl
  ivec2 texel = iceScreenTexel();
  float front = texelFetch(iceDepthInterval, texel, 0).r;
  if (front > 1.0e30)
  {
    discard;
  }
  // The front face's point: on the pixel's ray through the near and far planes, at its depth.
  vec2 ndc = 2.0 * texCoord - 1.0; // the quad's texture coordinates: the pixel centre's
  vec4 nearWC = iceDCWCMatrix * vec4(ndc, -1.0, 1.0);
  vec4 farWC = iceDCWCMatrix * vec4(ndc, 1.0, 1.0);
  vec3 a = nearWC.xyz / nearWC.w;
  vec3 b = farWC.xyz / farWC.w;
  float depthA = dot(a - iceCameraWC, iceViewDirectionWC);
  float depthB = dot(b - iceCameraWC, iceViewDirectionWC);
  vec3 positionWC = mix(a, b, (front - depthA) / (depthB - depthA));
  vec3 positionMC = (iceWCMCMatrix * vec4(positionWC, 1.0)).xyz;
  gl_FragData[0] = iceInteriorAlong(
    positionWC, positionMC, front, texelFetch(iceBackNormals, texel, 0).a);
  gl_FragDepth = clamp(iceWindowDepth(front), 0.0, 1.0);
