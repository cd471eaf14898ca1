// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
// The back-face target of vtkIceBackfaceNormalPass, handed over by vtkIcePass: RGB the nearest
// back face's world normal, A its view depth (0: no ice). Declared here only; compiled where the
// frame defines ICE_FRAME_BACK_NORMALS, before every part that samples it (vtkIceMapper).
uniform sampler2D iceBackNormals;
