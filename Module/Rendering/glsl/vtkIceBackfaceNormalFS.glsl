// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Impl
  // Keep only back faces (front faces culled) and store their world-space normal and view depth
  // (alpha: 0 where there is no ice, so kept above 0).
  if (gl_FrontFacing) { discard; }
  gl_FragData[0] = vec4(normalize(iceNormalWCVSOutput), max(iceViewDepth(), 1.0e-6));
//ICE::Crack
  {
    // A crack inside the ice acts as a back face: its normal, turned away from the viewer, at its
    // own depth (the overlay shader moves cracks to the ice's front depth).
    // Seen nearly edge-on (its normal within about 14 degrees of square to the view) it is left out: a normal
    // across the view would swing the refraction far aside (a dark jagged line along the crack),
    // while the sheet itself covers almost nothing there.
    vec3 crackNormal = normalize(iceNormalWCVSOutput);
    float facing = dot(crackNormal, iceViewDirectionWC);
    if (abs(facing) < 0.25) { discard; }
    if (facing < 0.0) { crackNormal = -crackNormal; }
    gl_FragData[0] = vec4(crackNormal, max(iceViewDepth(), 1.0e-6));
    gl_FragDepth = gl_FragCoord.z;
  }
