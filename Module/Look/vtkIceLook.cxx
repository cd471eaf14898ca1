// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceLook.h"

#include "vtkCamera.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceLookTable.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkIceLook);

namespace
{
const vtkIceLookTable::Setting* At(int i)
{
  const auto& settings = vtkIceLookTable::Settings();
  return i >= 0 && i < static_cast<int>(settings.size()) ? &settings[i] : nullptr;
}

// The table's settings act on all four without checking them: refuse a scene that lacks one.
bool Complete(const vtkIceLookTable::Target& target)
{
  return target.Mapper && target.Pass && target.CubeMaps && target.Camera;
}

const char* const NoScene = "vtkIceLook needs a mapper, a pass, a cube-map pass and a camera";
}

//------------------------------------------------------------------------------
void vtkIceLook::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSettings: " << vtkIceLook::GetNumberOfSettings() << "\n";
}

//------------------------------------------------------------------------------
int vtkIceLook::GetNumberOfSettings()
{
  return static_cast<int>(vtkIceLookTable::Settings().size());
}

//------------------------------------------------------------------------------
int vtkIceLook::FindSetting(const char* name)
{
  for (int i = 0; name && i < vtkIceLook::GetNumberOfSettings(); ++i)
  {
    if (std::string(name) == At(i)->Name)
    {
      return i;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
const char* vtkIceLook::GetName(int i)
{
  const vtkIceLookTable::Setting* setting = At(i);
  return setting ? setting->Name : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkIceLook::GetKind(int i)
{
  const vtkIceLookTable::Setting* setting = At(i);
  if (!setting)
  {
    return nullptr;
  }
  switch (setting->Type)
  {
    case vtkIceLookTable::Kind::Number:
      return "number";
    case vtkIceLookTable::Kind::Integer:
      return "integer";
    case vtkIceLookTable::Kind::Switch:
      return "switch";
    case vtkIceLookTable::Kind::Choice:
      return "choice";
    case vtkIceLookTable::Kind::Vector:
      return "vector";
  }
  return nullptr;
}

//------------------------------------------------------------------------------
const char* vtkIceLook::GetHelp(int i)
{
  const vtkIceLookTable::Setting* setting = At(i);
  return setting ? setting->Help : nullptr;
}

//------------------------------------------------------------------------------
bool vtkIceLook::IsCameraSetting(int i)
{
  const vtkIceLookTable::Setting* setting = At(i);
  return setting && setting->Camera;
}

//------------------------------------------------------------------------------
const char* vtkIceLook::GetSynonymOf(int i)
{
  const vtkIceLookTable::Setting* setting = At(i);
  return setting ? setting->SynonymOf : nullptr;
}

//------------------------------------------------------------------------------
double vtkIceLook::GetMinimum(int i)
{
  double low = 0.0, high = 0.0;
  return At(i) && vtkIceLookTable::Bounds(At(i)->Name, low, high) ? low : 0.0;
}

//------------------------------------------------------------------------------
double vtkIceLook::GetMaximum(int i)
{
  double low = 0.0, high = 0.0;
  return At(i) && vtkIceLookTable::Bounds(At(i)->Name, low, high) ? high : 0.0;
}

//------------------------------------------------------------------------------
int vtkIceLook::GetNumberOfChoices(int i)
{
  return At(i) ? static_cast<int>(vtkIceLookTable::Choices(At(i)->Name).size()) : 0;
}

//------------------------------------------------------------------------------
const char* vtkIceLook::GetChoice(int i, int choice)
{
  if (choice < 0 || choice >= vtkIceLook::GetNumberOfChoices(i))
  {
    return nullptr;
  }
  // The table's own strings: they live as long as the library.
  return vtkIceLookTable::Choices(At(i)->Name)[choice].c_str();
}

//------------------------------------------------------------------------------
std::string vtkIceLook::GetDefault(int i)
{
  return At(i) ? vtkIceLookTable::Default(At(i)->Name) : std::string();
}

//------------------------------------------------------------------------------
std::string vtkIceLook::Apply(vtkIceMapper* mapper, vtkIcePass* pass, vtkIceCubeMapPass* cubeMaps,
  vtkCamera* camera, const char* name, const char* value)
{
  return vtkIceLook::Apply(mapper, pass, cubeMaps, camera, nullptr, name, value);
}

//------------------------------------------------------------------------------
std::string vtkIceLook::Apply(vtkIceMapper* mapper, vtkIcePass* pass, vtkIceCubeMapPass* cubeMaps,
  vtkCamera* camera, vtkToneMappingPass* toneMapping, const char* name, const char* value)
{
  const vtkIceLookTable::Target target{ mapper, pass, cubeMaps, camera, toneMapping };
  if (!Complete(target))
  {
    return NoScene;
  }
  return vtkIceLookTable::Apply(target, name ? name : "", value ? value : "");
}

//------------------------------------------------------------------------------
std::string vtkIceLook::GetValue(vtkIceMapper* mapper, vtkIcePass* pass,
  vtkIceCubeMapPass* cubeMaps, vtkCamera* camera, const char* name)
{
  return vtkIceLook::GetValue(mapper, pass, cubeMaps, camera, nullptr, name);
}

//------------------------------------------------------------------------------
std::string vtkIceLook::GetValue(vtkIceMapper* mapper, vtkIcePass* pass,
  vtkIceCubeMapPass* cubeMaps, vtkCamera* camera, vtkToneMappingPass* toneMapping, const char* name)
{
  const vtkIceLookTable::Target target{ mapper, pass, cubeMaps, camera, toneMapping };
  return Complete(target) && name ? vtkIceLookTable::Value(target, name) : std::string();
}

//------------------------------------------------------------------------------
std::string vtkIceLook::ApplyPreset(vtkIceMapper* mapper, vtkIcePass* pass,
  vtkIceCubeMapPass* cubeMaps, vtkCamera* camera, const char* path)
{
  return vtkIceLook::ApplyPreset(mapper, pass, cubeMaps, camera, nullptr, path);
}

//------------------------------------------------------------------------------
std::string vtkIceLook::ApplyPreset(vtkIceMapper* mapper, vtkIcePass* pass,
  vtkIceCubeMapPass* cubeMaps, vtkCamera* camera, vtkToneMappingPass* toneMapping, const char* path)
{
  const vtkIceLookTable::Target target{ mapper, pass, cubeMaps, camera, toneMapping };
  if (!Complete(target))
  {
    return NoScene;
  }
  vtkIceLookTable::Assignments assignments;
  const std::string problem = vtkIceLookTable::ReadPreset(path ? path : "", assignments);
  // ReadPreset checked every line on a scratch scene, so applying cannot stop half-way.
  return problem.empty() ? vtkIceLookTable::ApplyAll(target, assignments) : problem;
}

//------------------------------------------------------------------------------
void vtkIceLook::ResetToneMapping(vtkToneMappingPass* toneMapping)
{
  if (toneMapping)
  {
    vtkIceLookTable::ResetToneMapping(toneMapping);
  }
}

//------------------------------------------------------------------------------
bool vtkIceLook::AsksForToneMapping(vtkToneMappingPass* toneMapping)
{
  return toneMapping && vtkIceLookTable::AsksForToneMapping(toneMapping);
}
