//ICE::Impl
  // Keep only back faces (front faces culled) and store their world-space normal.
  if (gl_FrontFacing) { discard; }
  gl_FragData[0] = vec4(normalize(iceNormalWC), 1.0);
