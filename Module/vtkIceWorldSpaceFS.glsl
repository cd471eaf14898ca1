//ICE::Dec
in vec3 icePositionWC;
in vec3 iceNormalWC;
uniform vec3 iceCameraWC;
uniform vec3 iceViewDirectionWC; // unit direction of projection
uniform ivec2 iceViewportOrigin; // window position of texel (0, 0) of viewport-sized textures

// Distance of this fragment in front of the camera along the view direction (-z in view space).
float iceViewDepth()
{
  return dot(icePositionWC - iceCameraWC, iceViewDirectionWC);
}

// Texel of a viewport-sized texture under this fragment.
ivec2 iceScreenTexel()
{
  return ivec2(gl_FragCoord.xy) - iceViewportOrigin;
}
