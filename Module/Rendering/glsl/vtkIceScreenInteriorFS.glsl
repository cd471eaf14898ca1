// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
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
// its own nearest front face (the view depth in the depth interval's R, its normal in B and A;
// FLT_MAX: none) to the nearest back face of the ice (the back-face target's alpha), written as
// vec4(add, keep), composed in front of what the target holds (the core, the air planes and the
// rest drawn one after the other). The quad reaches only the prop's front faces (depth test);
// where ice props overlap, only the nearest one's (Nearest, below).
uniform sampler2D iceDepthInterval;
uniform sampler2D iceBackNormals;
uniform mat4 iceDCWCMatrix; // normalised device coordinates to world
//ICE::Impl
  ivec2 texel = iceScreenTexel();
  vec4 frontTexel = texelFetch(iceDepthInterval, texel, 0);
  float front = frontTexel.r;
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
  vec3 normalWC = iceDecodeNormal(frontTexel.ba);
  vec4 backHere = texelFetch(iceBackNormals, texel, 0);
#ifdef ICE_INTERIOR_CLOUD
  // The width of a pixel at depthA and depthB, from the next pixel's ray: linear in the depth.
  float nextX = ndc.x + 2.0 / float(textureSize(iceDepthInterval, 0).x);
  vec4 nearNext = iceDCWCMatrix * vec4(nextX, ndc.y, -1.0, 1.0);
  vec4 farNext = iceDCWCMatrix * vec4(nextX, ndc.y, 1.0, 1.0);
  float widthA = length(nearNext.xyz / nearNext.w - a);
  float widthB = length(farNext.xyz / farNext.w - b);
  float widthSlope = (widthB - widthA) / (depthB - depthA);
  icePixelFootprint = vec2(widthA - depthA * widthSlope, widthSlope);
  // The refracted ray's own length in the ice, for the cloud and the bubbles along it.
  vec3 eyeWC = iceEyeVectorWC(positionWC);
  vec3 refractedWC = iceRefract(
    eyeWC, dot(normalWC, eyeWC) < 0.0 ? normalWC : -normalWC, iceRefractionRatio);
  vec4 exitTexel;
  float cloudLength =
    backHere.a > 0.0 ? iceExitDistance(positionWC, refractedWC, backHere, exitTexel) : 0.0;
#else
  vec3 refractedWC = vec3(0.0);
  float cloudLength = 0.0;
#endif
  gl_FragData[0] =
    iceInteriorAlong(positionWC, positionMC, refractedWC, front, backHere.a, cloudLength);
//ICE::AirVS
// The air planes' quads (vtkIceScreenAir): corners in world coordinates (in VTK's helper's
// attribute names), the bubble images' atlas coordinates.
//VTK::System::Dec
in vec4 vertexMC;
in vec2 tcoordMC;
uniform mat4 iceWCDCMatrix;
out vec3 iceAirPositionWC;
out vec2 iceAirAtlasCoordinates;
void main()
{
  iceAirPositionWC = vertexMC.xyz;
  iceAirAtlasCoordinates = tcoordMC;
  gl_Position = iceWCDCMatrix * vertexMC;
}
//ICE::AirFS
//VTK::System::Dec
//VTK::Output::Dec
in vec3 iceAirPositionWC;
in vec2 iceAirAtlasCoordinates;
//ICEHOOK::AirDeclarations
void main()
{
  vec4 back = texelFetch(iceBackNormals, iceScreenTexel(), 0);
  gl_FragData[0] = iceAirPlane(iceAirPositionWC, texture(iceAirAtlas, iceAirAtlasCoordinates),
#ifdef ICE_INTERIOR_CLOUD
    texelFetch(iceDepthInterval, iceScreenTexel(), 0).r,
#else
    0.0,
#endif
    back.a);
}
//ICE::NearestDec
// Where several ice props have an interior, a draw before the others moves the prop's front
// faces' window depth to the far plane wherever another ice prop's front faces are nearer: the
// depth test then keeps the quads (on the far plane) and the air planes (behind the front faces)
// off those pixels, and they read no other prop's depth themselves (a texel fetch per air plane
// and pixel, which llvmpipe pays for).
uniform sampler2D iceDepthInterval; // R: the prop's front faces' view depth
uniform sampler2D iceNearestFront;  // R: the nearest front faces' view depth of all the ice
//ICE::NearestImpl
  // The quad's texture coordinates (the pixel centre's) in texels.
  ivec2 texel = ivec2(texCoord * vec2(textureSize(iceDepthInterval, 0)));
  if (texelFetch(iceDepthInterval, texel, 0).r <= texelFetch(iceNearestFront, texel, 0).r)
  {
    discard;
  }
  gl_FragDepth = 1.0;
