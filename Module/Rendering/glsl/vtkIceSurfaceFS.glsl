// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
//ICE::Environment
// The environment the surface refracts and mirrors (also the screen-space interior's, whose crack
// sheets mirror it).
uniform samplerCube iceEnvironment;
// World direction to the environment texture's lookup direction, and how to show its colours as
// the skybox of the same texture shows them: 0 as sampled, 1 gamma-corrected
// (vtkIceStaticEnvironment). The surface compiles the space in as ICE_ENVIRONMENT_SPACE (llvmpipe
// would run the power for every lookup); elsewhere it is this uniform.
uniform mat3 iceEnvironmentMatrix;
uniform int iceEnvironmentColorSpace;
#ifndef ICE_ENVIRONMENT_SPACE
#define ICE_ENVIRONMENT_SPACE iceEnvironmentColorSpace
#endif
vec3 iceEnvironmentColor(vec3 directionWC)
{
  vec3 color = texture(iceEnvironment, iceEnvironmentMatrix * directionWC).rgb;
  return ICE_ENVIRONMENT_SPACE == 0 ? color : pow(max(color, vec3(0.0)), vec3(1.0 / 2.2));
}
// The environment seen through the surface and mirrored by it: with Roughness, its prefiltered
// copy (vtkIcePrefilteredEnvironment) at the level of the surface's roughness.
#ifdef ICE_ROUGH_ENVIRONMENT
uniform samplerCube iceEnvironmentPrefiltered;
uniform float iceRoughnessLevel;
uniform float iceRoughnessAlpha; // GGX's alpha, roughness^2
vec3 icePrefilteredEnvironmentColor(vec3 directionWC, float level)
{
  vec3 color =
    textureLod(iceEnvironmentPrefiltered, iceEnvironmentMatrix * directionWC, level).rgb;
  return ICE_ENVIRONMENT_SPACE == 0 ? color : pow(max(color, vec3(0.0)), vec3(1.0 / 2.2));
}
vec3 iceSurfaceEnvironmentColor(vec3 directionWC)
{
  return icePrefilteredEnvironmentColor(directionWC, iceRoughnessLevel);
}
#else
vec3 iceSurfaceEnvironmentColor(vec3 directionWC)
{
  return iceEnvironmentColor(directionWC);
}
#endif
//ICE::Dec
in float iceFresnelFactorVSOutput;
uniform float iceRefractionRatio;
uniform float iceDielectricFresnel; // 1: vtkIceProperty::FresnelDielectric
uniform vec3 iceTint;
uniform vec3 iceAttenuationColor;
uniform float iceInverseAttenuationDistance;
// 1 where the colours around the ice are linear light, 1/2.2 where they are gamma-encoded
// (vtkIceStaticEnvironment::ShowsEncodedLight): the power absorption takes on them.
uniform float iceAbsorptionPower;
//ICE::Impl
  {
    vec3 e = iceEyeVectorWC(icePositionWCVSOutput);
    vec3 nFront = normalize(iceNormalWCVSOutput);
    if (gl_FrontFacing == false) { nFront = -nFront; }
    float fresnel = iceFresnelFactorVSOutput;
    //ICEHOOK::SurfaceNormal
    if (iceDielectricFresnel > 0.5)
    {
      fresnel = iceDielectricReflectance(dot(e, nFront), iceRefractionRatio);
    }
    vec3 nRefract = nFront;
    //ICEHOOK::RefractionNormal
    vec3 refractedDirection = iceRefract(e, nRefract, iceRefractionRatio);
    float iceExitPathLength = 0.0;
    //ICEHOOK::RefractionDirection
    // The refracted light's path in the ice, where vtkIcePass knows the back faces (0: none).
    float icePathLength = 0.0;
    //ICEHOOK::PathLength
    vec3 refracted = iceSurfaceEnvironmentColor(refractedDirection) *
      iceTransmittance(icePathLength, iceAttenuationColor,
        iceInverseAttenuationDistance * iceAbsorptionPower);
    //ICEHOOK::Refracted
    vec3 reflected = iceSurfaceEnvironmentColor(iceReflect(e, nFront));
    vec3 iceColor = iceTint;
    //ICEHOOK::ScalarColor
    gl_FragData[0].rgb = iceColor * mix(refracted, reflected, clamp(fresnel, 0.0, 1.0));
    //ICEHOOK::Interior
    //ICEHOOK::Glistening
    //ICEHOOK::Debug
    //ICEHOOK::Edges
  }
  //ICEHOOK::Output
