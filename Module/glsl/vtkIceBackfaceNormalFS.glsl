//ICE::Impl
  // Keep only back faces (front faces culled) and store their world-space normal.
  if (gl_FrontFacing) { discard; }
  gl_FragData[0] = vec4(normalize(iceNormalWCVSOutput), 1.0);
//ICE::Crack
  {
    // A crack inside the ice acts as a back face: its normal, turned away from the viewer, at its
    // own depth (the overlay shader moves cracks to the ice's front depth).
    vec3 crackNormal = normalize(iceNormalWCVSOutput);
    if (dot(crackNormal, iceViewDirectionWC) < 0.0) { crackNormal = -crackNormal; }
    gl_FragData[0] = vec4(crackNormal, 1.0);
    gl_FragDepth = gl_FragCoord.z;
  }
