// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
in vec2 iceAirUVMC;
out vec2 iceAirUVVSOutput;
//ICE::Impl
  iceAirUVVSOutput = iceAirUVMC;
