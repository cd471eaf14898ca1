// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceProperty.h"

#include "vtkObjectFactory.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkIceProperty);

namespace
{
// Clamps `value` to [low, high] into `member` as vtkSetClampMacro does, but refuses NaN (which
// the macro would store: every comparison with NaN is false) with a warning naming the
// parameter. Returns whether `member` changed.
bool SetClamped(
  vtkObject* self, const char* name, double value, double low, double high, double& member)
{
  if (std::isnan(value))
  {
    vtkWarningWithObjectMacro(
      self, << "Set" << name << "(NaN) ignored: " << name << " stays " << member << ".");
    return false;
  }
  const double clamped = std::min(std::max(value, low), high);
  if (clamped == member)
  {
    return false;
  }
  member = clamped;
  return true;
}

// A colour: components clamped to [0, 1], a colour with a NaN component refused with a warning.
bool SetColor(vtkObject* self, const char* name, const double color[3], double member[3])
{
  if (std::isnan(color[0]) || std::isnan(color[1]) || std::isnan(color[2]))
  {
    vtkWarningWithObjectMacro(self, << "Set" << name << "(" << color[0] << ", " << color[1] << ", "
                                    << color[2] << ") ignored: a component is NaN; " << name
                                    << " stays (" << member[0] << ", " << member[1] << ", "
                                    << member[2] << ").");
    return false;
  }
  bool changed = false;
  for (int i = 0; i < 3; ++i)
  {
    changed = SetClamped(self, name, color[i], 0.0, 1.0, member[i]) || changed;
  }
  return changed;
}
}

//------------------------------------------------------------------------------
vtkIceProperty::vtkIceProperty()
  : AttenuationDistance(std::numeric_limits<double>::infinity())
{
}

//------------------------------------------------------------------------------
vtkIceProperty::~vtkIceProperty() = default;

//------------------------------------------------------------------------------
// The clamped floating-point parameters: clamped to the ranges their header declares, NaN
// refused with a warning.
#define vtkIceClampedSetter(name)                                                                  \
  void vtkIceProperty::Set##name(double value)                                                     \
  {                                                                                                \
    if (SetClamped(this, #name, value, this->Get##name##MinValue(), this->Get##name##MaxValue(),   \
          this->name))                                                                             \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }
vtkIceClampedSetter(FresnelPower)
vtkIceClampedSetter(BackNormalWeight)
vtkIceClampedSetter(Roughness)
vtkIceClampedSetter(CrackIntensity)
vtkIceClampedSetter(CrackReflection)
vtkIceClampedSetter(Milkiness)
vtkIceClampedSetter(MilkyCoreRadius)
vtkIceClampedSetter(BubbleDensity)
vtkIceClampedSetter(BumpStrength)
vtkIceClampedSetter(BumpScale)
vtkIceClampedSetter(GlisteningScale)
vtkIceClampedSetter(GlisteningIntensity)
vtkIceClampedSetter(GlisteningAlignmentGain)
vtkIceClampedSetter(SnowAmount)
vtkIceClampedSetter(AttenuationDistance)
#undef vtkIceClampedSetter

//------------------------------------------------------------------------------
void vtkIceProperty::SetIceColor(double red, double green, double blue)
{
  const double color[3] = { red, green, blue };
  if (SetColor(this, "IceColor", color, this->IceColor))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkIceProperty::SetAttenuationColor(double red, double green, double blue)
{
  const double color[3] = { red, green, blue };
  if (SetColor(this, "AttenuationColor", color, this->AttenuationColor))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkIceProperty::SetIndexOfRefraction(double ior)
{
  // Both are kept as set, so each reads back exactly what was given.
  if (SetClamped(this, "IndexOfRefraction", ior, this->GetIndexOfRefractionMinValue(),
        this->GetIndexOfRefractionMaxValue(), this->IndexOfRefraction))
  {
    this->RefractionRatio = 1.0 / this->IndexOfRefraction;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkIceProperty::SetRefractionRatio(double eta)
{
  if (SetClamped(this, "RefractionRatio", eta, this->GetRefractionRatioMinValue(),
        this->GetRefractionRatioMaxValue(), this->RefractionRatio))
  {
    this->IndexOfRefraction = 1.0 / this->RefractionRatio;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkIceProperty::GetAttenuationDistanceMaxValue()
{
  return std::numeric_limits<double>::infinity();
}

//------------------------------------------------------------------------------
bool vtkIceProperty::Absorbs() const
{
  return std::isfinite(this->AttenuationDistance) &&
    (this->AttenuationColor[0] < 1.0 || this->AttenuationColor[1] < 1.0 ||
      this->AttenuationColor[2] < 1.0);
}

//------------------------------------------------------------------------------
void vtkIceProperty::SetNormalMap(vtkTexture* texture)
{
  if (this->NormalMap != texture)
  {
    this->NormalMap = texture;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkTexture* vtkIceProperty::GetNormalMap()
{
  return this->NormalMap;
}

//------------------------------------------------------------------------------
void vtkIceProperty::DeepCopy(vtkIceProperty* other)
{
  if (!other || other == this)
  {
    return;
  }
  this->IndexOfRefraction = other->IndexOfRefraction;
  this->RefractionRatio = other->RefractionRatio;
  std::copy(other->AttenuationColor, other->AttenuationColor + 3, this->AttenuationColor);
  this->AttenuationDistance = other->AttenuationDistance;
  this->FresnelPower = other->FresnelPower;
  this->FresnelModel = other->FresnelModel;
  this->BackNormalWeight = other->BackNormalWeight;
  std::copy(other->IceColor, other->IceColor + 3, this->IceColor);
  this->Roughness = other->Roughness;
  this->NumberOfCracks = other->NumberOfCracks;
  this->CrackSeed = other->CrackSeed;
  this->CrackIntensity = other->CrackIntensity;
  this->CrackReflection = other->CrackReflection;
  this->NumberOfAirPlanes = other->NumberOfAirPlanes;
  this->AirSeed = other->AirSeed;
  this->Milkiness = other->Milkiness;
  this->MilkyCoreRadius = other->MilkyCoreRadius;
  this->BubbleDensity = other->BubbleDensity;
  this->BumpStrength = other->BumpStrength;
  this->BumpScale = other->BumpScale;
  this->NormalMap = other->NormalMap;
  this->Glistening = other->Glistening;
  this->GlisteningScale = other->GlisteningScale;
  this->GlisteningIntensity = other->GlisteningIntensity;
  this->GlisteningAlignmentGain = other->GlisteningAlignmentGain;
  this->SnowAmount = other->SnowAmount;
  this->Modified();
}

//------------------------------------------------------------------------------
std::array<vtkIceProperty::ShaderValue, 8> vtkIceProperty::GetShaderValues() const
{
  auto scalar = [](const char* name, double value, bool optional) {
    return ShaderValue{ name, 1, { static_cast<float>(value), 0.0f, 0.0f }, optional };
  };
  auto color = [](const char* name, const double value[3]) {
    return ShaderValue{ name, 3,
      { static_cast<float>(value[0]), static_cast<float>(value[1]), static_cast<float>(value[2]) },
      false };
  };
  return { color("iceTint", this->IceColor),
    scalar("iceRefractionRatio", this->RefractionRatio, false),
    color("iceAttenuationColor", this->AttenuationColor),
    scalar("iceInverseAttenuationDistance", 1.0 / this->AttenuationDistance, false),
    scalar("iceFresnelPower", this->FresnelPower, false),
    scalar("iceDielectricFresnel", this->FresnelModel == FresnelDielectric ? 1.0 : 0.0, true),
    // In the programs of some parts only.
    scalar("iceBackNormalWeight", this->BackNormalWeight, true),
    scalar("iceBumpStrength", this->BumpStrength, true) };
}

//------------------------------------------------------------------------------
void vtkIceProperty::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IndexOfRefraction: " << this->IndexOfRefraction << "\n";
  os << indent << "RefractionRatio: " << this->RefractionRatio << "\n";
  os << indent << "AttenuationColor: (" << this->AttenuationColor[0] << ", "
     << this->AttenuationColor[1] << ", " << this->AttenuationColor[2] << ")\n";
  os << indent << "AttenuationDistance: " << this->AttenuationDistance << "\n";
  os << indent << "FresnelPower: " << this->FresnelPower << "\n";
  os << indent << "FresnelModel: "
     << (this->FresnelModel == FresnelDielectric ? "Dielectric" : "Paper") << "\n";
  os << indent << "BackNormalWeight: " << this->BackNormalWeight << "\n";
  os << indent << "IceColor: (" << this->IceColor[0] << ", " << this->IceColor[1] << ", "
     << this->IceColor[2] << ")\n";
  os << indent << "Roughness: " << this->Roughness << "\n";
  os << indent << "NumberOfCracks: " << this->NumberOfCracks << "\n";
  os << indent << "CrackSeed: " << this->CrackSeed << "\n";
  os << indent << "CrackIntensity: " << this->CrackIntensity << "\n";
  os << indent << "CrackReflection: " << this->CrackReflection << "\n";
  os << indent << "NumberOfAirPlanes: " << this->NumberOfAirPlanes << "\n";
  os << indent << "AirSeed: " << this->AirSeed << "\n";
  os << indent << "Milkiness: " << this->Milkiness << "\n";
  os << indent << "MilkyCoreRadius: " << this->MilkyCoreRadius << "\n";
  os << indent << "BubbleDensity: " << this->BubbleDensity << "\n";
  os << indent << "BumpStrength: " << this->BumpStrength << "\n";
  os << indent << "BumpScale: " << this->BumpScale << "\n";
  os << indent << "NormalMap: " << this->NormalMap.Get() << "\n";
  os << indent << "Glistening: " << (this->Glistening ? "On" : "Off") << "\n";
  os << indent << "GlisteningScale: " << this->GlisteningScale << "\n";
  os << indent << "GlisteningIntensity: " << this->GlisteningIntensity << "\n";
  os << indent << "GlisteningAlignmentGain: " << this->GlisteningAlignmentGain << "\n";
  os << indent << "SnowAmount: " << this->SnowAmount << "\n";
}
