// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Dec
uniform float iceBumpStrength;
uniform float iceBumpFrequency; // noise cycles per model unit
uniform float iceFresnelPower;
//ICE::Impl
    // A bumpy surface: the normal tilts with the gradient of a noise field fixed to the model, and
    // the tilted normal drives reflection, refraction and a per-fragment Fresnel term.
    nFront = iceBumpNormal(nFront,
      iceNormalMCWCMatrix * iceNoiseGradient(icePositionMCVSOutput * iceBumpFrequency), iceBumpStrength);
    fresnel = iceFresnel(e, nFront, iceFresnelPower);
