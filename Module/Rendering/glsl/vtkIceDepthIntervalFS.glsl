// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
uniform int iceDepthStage; // 0: front faces, 1: back faces
//ICE::Impl
  // Front faces in the first stage, back faces in the second; both store the view depth.
  if (gl_FrontFacing != (iceDepthStage == 0)) { discard; }
  gl_FragData[0] = vec4(iceViewDepth(), iceViewDepth(), 0.0, 1.0);
