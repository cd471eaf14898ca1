// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
uniform float iceFresnelPower;
out float iceFresnelFactorVSOutput;
//ICE::Impl
  iceFresnelFactorVSOutput = iceFresnel(iceEyeVectorWC(icePositionWCVSOutput), normalize(iceNormalWCVSOutput),
    iceFresnelPower);
