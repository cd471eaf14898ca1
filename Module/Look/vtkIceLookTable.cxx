// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceLookTable.h"

#include "vtkCamera.h"
#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"
#include "vtkNew.h"
#include "vtkToneMappingPass.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>

namespace vtkIceLookTable
{
namespace
{
using Getter = std::function<double(const Target&)>;
using Setter = std::function<void(const Target&, double)>;
using Bound = std::function<double(vtkIceMapper*, vtkIceCubeMapPass*)>;

struct Entry
{
  Setting Info;
  std::vector<std::string> Names; // Choice: the accepted names, in enum order
  Bound Low;                      // Number, Integer: the library's range
  Bound High;
  Getter Get; // Number, Integer, Switch (0/1), Choice (index)
  Setter Set;
  std::function<void(const Target&, double*)> GetVector; // Vector
  std::function<void(const Target&, const double*)> SetVector;
  bool ToneMapping = false; // set on Target::ToneMapping, which must be there
};

std::string Format(double value)
{
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0' && std::isfinite(value);
}

// The table. Mapper and cube-map parameters read their ranges from the library itself.
std::vector<Entry> MakeEntries()
{
  std::vector<Entry> e;
  auto number = [&e](const char* name, const char* help, Bound low, Bound high, Getter get,
                  Setter set, Kind kind = Kind::Number) {
    Entry entry;
    entry.Info = { name, kind, help, false };
    entry.Low = low;
    entry.High = high;
    entry.Get = get;
    entry.Set = set;
    e.push_back(entry);
  };
  auto toggle = [&e](const char* name, const char* help, Getter get, Setter set) {
    Entry entry;
    entry.Info = { name, Kind::Switch, help, false };
    entry.Get = get;
    entry.Set = set;
    e.push_back(entry);
  };
  auto choice = [&e](const char* name, const char* help, std::vector<std::string> names, Getter get,
                  Setter set) {
    Entry entry;
    entry.Info = { name, Kind::Choice, help, false };
    entry.Names = std::move(names);
    entry.Get = get;
    entry.Set = set;
    e.push_back(entry);
  };
// The look's parameters are the mapper's ice property's; how it is drawn is the mapper's.
#define ICE_PROPERTY_NUMBER(name, help, Property)                                                  \
  number(                                                                                          \
    name, help,                                                                                    \
    [](vtkIceMapper* m, vtkIceCubeMapPass*) {                                                      \
      return static_cast<double>(m->GetIceProperty()->Get##Property##MinValue());                  \
    },                                                                                             \
    [](vtkIceMapper* m, vtkIceCubeMapPass*) {                                                      \
      return static_cast<double>(m->GetIceProperty()->Get##Property##MaxValue());                  \
    },                                                                                             \
    [](const Target& t) {                                                                          \
      return static_cast<double>(t.Mapper->GetIceProperty()->Get##Property());                     \
    },                                                                                             \
    [](const Target& t, double v) { t.Mapper->GetIceProperty()->Set##Property(v); })
#define ICE_PROPERTY_INTEGER(name, help, Property)                                                 \
  ICE_PROPERTY_NUMBER(name, help, Property);                                                       \
  e.back().Info.Type = Kind::Integer
#define ICE_PROPERTY_SWITCH(name, help, Property)                                                  \
  toggle(                                                                                          \
    name, help,                                                                                    \
    [](const Target& t) { return t.Mapper->GetIceProperty()->Get##Property() ? 1.0 : 0.0; },       \
    [](const Target& t, double v) { t.Mapper->GetIceProperty()->Set##Property(v != 0.0); })
#define ICE_PROPERTY_COLOR(name, help, Property)                                                   \
  {                                                                                                \
    Entry color;                                                                                   \
    color.Info = { name, Kind::Vector, help, false };                                              \
    color.GetVector = [](const Target& t, double* v) {                                             \
      t.Mapper->GetIceProperty()->Get##Property(v);                                                \
    };                                                                                             \
    color.SetVector = [](const Target& t, const double* v) {                                       \
      t.Mapper->GetIceProperty()->Set##Property(v);                                                \
    };                                                                                             \
    e.push_back(color);                                                                            \
  }
#define ICE_MAPPER_SWITCH(name, help, Property)                                                    \
  toggle(                                                                                          \
    name, help, [](const Target& t) { return t.Mapper->Get##Property() ? 1.0 : 0.0; },             \
    [](const Target& t, double v) { t.Mapper->Set##Property(v != 0.0); })
#define ICE_MAPPER_CHOICE(name, help, Property, ...)                                               \
  choice(                                                                                          \
    name, help, { __VA_ARGS__ },                                                                   \
    [](const Target& t) { return static_cast<double>(t.Mapper->Get##Property()); },                \
    [](const Target& t, double v) { t.Mapper->Set##Property(static_cast<int>(v)); })
  const Bound anyLow = [](vtkIceMapper*, vtkIceCubeMapPass*) { return -2147483648.0; };
  const Bound anyHigh = [](vtkIceMapper*, vtkIceCubeMapPass*) { return 2147483647.0; };

  ICE_PROPERTY_NUMBER(
    "ior", "index of refraction of the ice (glTF's; 1.31 for ice)", IndexOfRefraction);
  // eta is ior's inverse as eq 2 writes it: air / ice, below 1 for ice. Above 1 it would be the
  // optics of air in something denser, which is what a user typing ice's 1.31 here does not mean.
  number(
    "eta", "ratio of refraction indices, air / ice (eq 2): 1 / ior",
    [](vtkIceMapper* m, vtkIceCubeMapPass*) {
      return m->GetIceProperty()->GetRefractionRatioMinValue();
    },
    [](vtkIceMapper*, vtkIceCubeMapPass*) { return 1.0; },
    [](const Target& t) { return t.Mapper->GetIceProperty()->GetRefractionRatio(); },
    [](const Target& t, double v) { t.Mapper->GetIceProperty()->SetRefractionRatio(v); });
  e.back().Info.SynonymOf = "ior";
  ICE_PROPERTY_COLOR("attenuation-color",
    "colour white light has after attenuation-distance in the ice, red,green,blue in [0, 1]",
    AttenuationColor);
  ICE_PROPERTY_NUMBER("attenuation-distance",
    "distance in the ice after which light has attenuation-color (inf: no absorption)",
    AttenuationDistance);
  ICE_PROPERTY_NUMBER("fresnel-power", "exponent P of the Fresnel term (eq 4)", FresnelPower);
  choice(
    "fresnel", "how much light the surface reflects: the paper's eq 4 or Fresnel's equations",
    { "paper", "dielectric" },
    [](const Target& t) {
      return static_cast<double>(t.Mapper->GetIceProperty()->GetFresnelModel());
    },
    [](const Target& t, double v) {
      t.Mapper->GetIceProperty()->SetFresnelModel(static_cast<int>(v));
    });
  ICE_PROPERTY_COLOR("color", "ice colour, red,green,blue each in [0, 1]", IceColor);
  ICE_MAPPER_SWITCH(
    "two-sided", "refract through the back faces too (with the pass)", TwoSidedRefraction);
  ICE_MAPPER_CHOICE("two-sided-method", "how two-sided refraction goes through the ice",
    TwoSidedMethod, "blended-normals", "exit-point");
  number(
    "bounces", "faces the light is followed through inside the ice (exit-point; 1: the exit point)",
    [](vtkIceMapper* m, vtkIceCubeMapPass*) { return m->GetMaxBouncesMinValue(); },
    [](vtkIceMapper* m, vtkIceCubeMapPass*) { return m->GetMaxBouncesMaxValue(); },
    [](const Target& t) { return static_cast<double>(t.Mapper->GetMaxBounces()); },
    [](const Target& t, double v) { t.Mapper->SetMaxBounces(static_cast<int>(v)); },
    Kind::Integer);
  ICE_PROPERTY_NUMBER(
    "back-normal-weight", "weight of the back normal (eq 1, blended-normals)", BackNormalWeight);
  ICE_PROPERTY_INTEGER("cracks", "number of crack surfaces inside the ice", NumberOfCracks);
  number(
    "crack-seed", "placement of the cracks", anyLow, anyHigh,
    [](const Target& t) { return static_cast<double>(t.Mapper->GetIceProperty()->GetCrackSeed()); },
    [](
      const Target& t, double v) { t.Mapper->GetIceProperty()->SetCrackSeed(static_cast<int>(v)); },
    Kind::Integer);
  ICE_PROPERTY_NUMBER("crack-intensity", "brightness of the cracks' highlights", CrackIntensity);
  ICE_PROPERTY_NUMBER("crack-reflection",
    "cracks as sheets mirroring the environment, 0 highlights only (screen-space)",
    CrackReflection);
  ICE_MAPPER_CHOICE("interior", "how cracks and air are rendered", InteriorMethod, "paper-passes",
    "screen-space");
  // The paper's passes' own settings (vtkIcePaperInterior).
  choice(
    "crack-clipping", "how cracks are kept inside the ice (paper-passes)",
    { "depth-interval", "geometry" },
    [](const Target& t) {
      return static_cast<double>(t.Mapper->GetPaperInterior()->GetCrackClipping());
    },
    [](const Target& t, double v) {
      t.Mapper->GetPaperInterior()->SetCrackClipping(static_cast<int>(v));
    });
  toggle(
    "cracks-in-refraction", "cracks bend the refraction like back faces",
    [](const Target& t) {
      return t.Mapper->GetPaperInterior()->GetCracksPerturbRefraction() ? 1.0 : 0.0;
    },
    [](const Target& t, double v) {
      t.Mapper->GetPaperInterior()->SetCracksPerturbRefraction(v != 0.0);
    });
  ICE_PROPERTY_INTEGER("air", "number of air-bubble planes", NumberOfAirPlanes);
  number(
    "air-seed", "placement and images of the air", anyLow, anyHigh,
    [](const Target& t) { return static_cast<double>(t.Mapper->GetIceProperty()->GetAirSeed()); },
    [](const Target& t, double v) { t.Mapper->GetIceProperty()->SetAirSeed(static_cast<int>(v)); },
    Kind::Integer);
  ICE_PROPERTY_NUMBER("milkiness", "0 clear bubbles, 1 white and cloudy", Milkiness);
  ICE_PROPERTY_NUMBER("milky-core",
    "a cloudy core of air at the centre, its radius a fraction of the model's half size (0: none)",
    MilkyCoreRadius);
  ICE_PROPERTY_NUMBER("bubbles",
    "small air bubbles as specks gathered in the core, a few in vertical streams (0: none)",
    BubbleDensity);
  ICE_PROPERTY_NUMBER("bumps", "strength of the surface bumps (0: smooth)", BumpStrength);
  ICE_PROPERTY_NUMBER("bump-scale", "size of the bumps, a fraction of the model", BumpScale);
  ICE_PROPERTY_NUMBER("roughness",
    "frost: how rough the surface is, 0 smooth to 1 matte (blurs reflection and refraction)",
    Roughness);
  ICE_PROPERTY_SWITCH("glistening", "direct light, rim light and crack glints", Glistening);
  ICE_PROPERTY_NUMBER(
    "snow", "snow over the whole surface, 0 ice to 1 snow (with glistening)", SnowAmount);
  ICE_PROPERTY_NUMBER("glistening-scale", "size of the glints", GlisteningScale);
  ICE_PROPERTY_NUMBER("glistening-intensity", "brightness of the glints", GlisteningIntensity);
  ICE_PROPERTY_NUMBER(
    "glistening-alignment", "how sharply glints follow the light", GlisteningAlignmentGain);
  ICE_MAPPER_CHOICE("debug-view", "the paper's Figure 5 views", DebugView, "off", "front-depth",
    "back-depth", "cracks-unclipped", "cracks-clipped", "air");

  toggle(
    "cube-map", "reflect and refract a cube map of the scene around the ice (dynamic)",
    [](const Target& t) { return t.Pass && t.Pass->GetCubeMapPass() ? 1.0 : 0.0; },
    [](const Target& t, double v) {
      if (t.Pass)
      {
        t.Pass->SetCubeMapPass(v != 0.0 ? t.CubeMaps : nullptr);
      }
    });
  choice(
    "cube-map-update", "when the dynamic cube map is rendered",
    { "every-frame", "on-change", "manual" },
    [](const Target& t) { return static_cast<double>(t.CubeMaps->GetUpdateMode()); },
    [](const Target& t, double v) { t.CubeMaps->SetUpdateMode(static_cast<int>(v)); });
#define ICE_CUBE_MAP_INTEGER(name, help, Property)                                                 \
  number(                                                                                          \
    name, help,                                                                                    \
    [](vtkIceMapper*, vtkIceCubeMapPass* c) {                                                      \
      return static_cast<double>(c->Get##Property##MinValue());                                    \
    },                                                                                             \
    [](vtkIceMapper*, vtkIceCubeMapPass* c) {                                                      \
      return static_cast<double>(c->Get##Property##MaxValue());                                    \
    },                                                                                             \
    [](const Target& t) { return static_cast<double>(t.CubeMaps->Get##Property()); },              \
    [](const Target& t, double v) { t.CubeMaps->Set##Property(static_cast<int>(v)); },             \
    Kind::Integer)
  ICE_CUBE_MAP_INTEGER("cube-map-size", "size of a cube-map face in pixels", FaceSize);
  ICE_CUBE_MAP_INTEGER("cube-map-faces", "cube-map faces rendered per frame", FacesPerFrame);
#undef ICE_CUBE_MAP_INTEGER
  toggle(
    "cube-map-culling", "leave props outside a face out of its render",
    [](const Target& t) { return t.CubeMaps->GetFrustumCulling() ? 1.0 : 0.0; },
    [](const Target& t, double v) { t.CubeMaps->SetFrustumCulling(v != 0.0); });

  // How the picture's light becomes screen values: VTK's vtkToneMappingPass around the ice pass
  // ("none" is its Clamp). VTK applies the exposure in its exponential and filmic curves only.
  choice(
    "tone-mapping", "how HDR light is mapped to the screen; none clips it at white",
    { "none", "reinhard", "exponential", "filmic", "aces" },
    [](const Target& t) {
      const int type = t.ToneMapping->GetToneMappingType();
      return type == vtkToneMappingPass::GenericFilmic && t.ToneMapping->GetUseACES() ? 4.0 : type;
    },
    [](const Target& t, double v) {
      const int choice = static_cast<int>(v);
      t.ToneMapping->SetToneMappingType(std::min(choice, 3));
      t.ToneMapping->SetUseACES(choice == 4);
    });
  e.back().ToneMapping = true;
  number(
    "exposure", "exposure in stops (EV): +1 doubles the light (exponential, filmic, aces)",
    [](vtkIceMapper*, vtkIceCubeMapPass*) { return -10.0; },
    [](vtkIceMapper*, vtkIceCubeMapPass*) { return 10.0; },
    [](const Target& t) { return std::log2(static_cast<double>(t.ToneMapping->GetExposure())); },
    [](
      const Target& t, double v) { t.ToneMapping->SetExposure(static_cast<float>(std::exp2(v))); });
  e.back().ToneMapping = true;
#undef ICE_PROPERTY_NUMBER
#undef ICE_PROPERTY_INTEGER
#undef ICE_PROPERTY_SWITCH
#undef ICE_PROPERTY_COLOR
#undef ICE_MAPPER_SWITCH
#undef ICE_MAPPER_CHOICE

  auto vector = [&e](const char* name, const char* help, void (vtkCamera::*get)(double[3]),
                  void (vtkCamera::*set)(const double[3])) {
    Entry entry;
    entry.Info = { name, Kind::Vector, help, true };
    entry.GetVector = [get](const Target& t, double* v) { (t.Camera->*get)(v); };
    entry.SetVector = [set](const Target& t, const double* v) { (t.Camera->*set)(v); };
    e.push_back(entry);
  };
  vector("camera-position", "where the camera is, x,y,z", &vtkCamera::GetPosition,
    &vtkCamera::SetPosition);
  vector("focal-point", "what the camera looks at, x,y,z", &vtkCamera::GetFocalPoint,
    &vtkCamera::SetFocalPoint);
  vector(
    "view-up", "the camera's up direction, x,y,z", &vtkCamera::GetViewUp, &vtkCamera::SetViewUp);
  {
    Entry angle;
    angle.Info = { "view-angle", Kind::Number, "the camera's vertical view angle in degrees",
      true };
    angle.Low = [](vtkIceMapper*, vtkIceCubeMapPass*) { return 1.0; };
    angle.High = [](vtkIceMapper*, vtkIceCubeMapPass*) { return 179.0; };
    angle.Get = [](const Target& t) { return t.Camera->GetViewAngle(); };
    angle.Set = [](const Target& t, double v) { t.Camera->SetViewAngle(v); };
    e.push_back(angle);
  }
  return e;
}

const std::vector<Entry>& Entries()
{
  static const std::vector<Entry> entries = MakeEntries();
  return entries;
}

const Entry* FindEntry(const std::string& name)
{
  for (const Entry& entry : Entries())
  {
    if (name == entry.Info.Name)
    {
      return &entry;
    }
  }
  return nullptr;
}

// A mapper and a cube-map pass with the library's defaults, for ranges and checks.
struct Scratch
{
  vtkNew<vtkIceMapper> Mapper;
  vtkNew<vtkIcePass> Pass;
  vtkNew<vtkIceCubeMapPass> CubeMaps;
  vtkNew<vtkCamera> Camera;
  vtkNew<vtkToneMappingPass> ToneMapping;
  Scratch() { ResetToneMapping(this->ToneMapping); }
  Target Get() const
  {
    return { this->Mapper, this->Pass, this->CubeMaps, this->Camera, this->ToneMapping };
  }
};

Scratch& Defaults()
{
  static Scratch scratch;
  return scratch;
}
}

//------------------------------------------------------------------------------
void ResetToneMapping(vtkToneMappingPass* pass)
{
  pass->SetToneMappingType(vtkToneMappingPass::Clamp);
  pass->SetExposure(1.0f);
  pass->SetUseACES(false);
}

//------------------------------------------------------------------------------
bool AsksForToneMapping(vtkToneMappingPass* pass)
{
  return pass->GetToneMappingType() != vtkToneMappingPass::Clamp;
}

//------------------------------------------------------------------------------
const std::vector<Setting>& Settings()
{
  static const std::vector<Setting> settings = [] {
    std::vector<Setting> list;
    for (const Entry& entry : Entries())
    {
      list.push_back(entry.Info);
    }
    return list;
  }();
  return settings;
}

//------------------------------------------------------------------------------
const Setting* Find(const std::string& name)
{
  const Entry* entry = FindEntry(name);
  return entry ? &entry->Info : nullptr;
}

//------------------------------------------------------------------------------
const std::vector<std::string>& Choices(const std::string& name)
{
  static const std::vector<std::string> none;
  const Entry* entry = FindEntry(name);
  return entry ? entry->Names : none;
}

//------------------------------------------------------------------------------
std::string Range(const std::string& name)
{
  const Entry* entry = FindEntry(name);
  if (!entry || !entry->Low)
  {
    return std::string();
  }
  Scratch& d = Defaults();
  return "[" + Format(entry->Low(d.Mapper, d.CubeMaps)) + ", " +
    Format(entry->High(d.Mapper, d.CubeMaps)) + "]";
}

//------------------------------------------------------------------------------
bool Bounds(const std::string& name, double& low, double& high)
{
  const Entry* entry = FindEntry(name);
  if (!entry || !entry->Low)
  {
    return false;
  }
  Scratch& d = Defaults();
  low = entry->Low(d.Mapper, d.CubeMaps);
  high = entry->High(d.Mapper, d.CubeMaps);
  return true;
}

//------------------------------------------------------------------------------
std::string Default(const std::string& name)
{
  static Scratch scene;
  static const bool dynamic = (scene.Pass->SetCubeMapPass(scene.CubeMaps), true);
  const Setting* setting = Find(name);
  return dynamic && setting && !setting->Camera ? Value(scene.Get(), name) : std::string();
}

//------------------------------------------------------------------------------
std::string Apply(const Target& target, const std::string& name, const std::string& value)
{
  const Entry* entry = FindEntry(name);
  if (!entry)
  {
    return "unknown setting '" + name + "'";
  }
  const std::string bad = "bad " + name + " '" + value + "'";
  if (entry->ToneMapping && !target.ToneMapping)
  {
    return name + " is set on the scene's vtkToneMappingPass, and none was given";
  }
  switch (entry->Info.Type)
  {
    case Kind::Number:
    case Kind::Integer:
    {
      double v;
      Scratch& d = Defaults();
      const double low = entry->Low(d.Mapper, d.CubeMaps);
      const double high = entry->High(d.Mapper, d.CubeMaps);
      const bool integer = entry->Info.Type == Kind::Integer;
      // "inf" where the range is unbounded (attenuation-distance: no absorption).
      const bool infinite = std::isinf(high) && (value == "inf" || value == "infinity");
      if (infinite)
      {
        v = high;
      }
      else if (!ParseNumber(value, v) || (integer && v != std::floor(v)) || v < low || v > high)
      {
        std::string why =
          bad + " (" + (integer ? "a whole number" : "a number") + " in " + Range(name) + ")";
        if (name == "eta" && ParseNumber(value, v) && v > high)
        {
          why += ": eta is air / ice, 1 / the index of refraction; for an index of refraction of " +
            value + " set ior (--ior " + value + ")";
        }
        return why;
      }
      entry->Set(target, v);
      return std::string();
    }
    case Kind::Switch:
      if (value != "on" && value != "off")
      {
        return bad + " (on or off)";
      }
      entry->Set(target, value == "on" ? 1.0 : 0.0);
      return std::string();
    case Kind::Choice:
      for (size_t i = 0; i < entry->Names.size(); ++i)
      {
        if (value == entry->Names[i])
        {
          entry->Set(target, static_cast<double>(i));
          return std::string();
        }
      }
      {
        std::string names;
        for (const std::string& n : entry->Names)
        {
          names += (names.empty() ? "" : ", ") + n;
        }
        return bad + " (one of " + names + ")";
      }
    case Kind::Vector:
    {
      double v[3];
      std::string rest = value;
      for (int i = 0; i < 3; ++i)
      {
        const auto comma = rest.find(',');
        const std::string part = i < 2 ? rest.substr(0, comma) : rest;
        if ((i < 2 && comma == std::string::npos) || !ParseNumber(part, v[i]))
        {
          return bad + " (three numbers x,y,z)";
        }
        rest = i < 2 ? rest.substr(comma + 1) : rest;
      }
      if ((name == "color" || name == "attenuation-color") &&
        (std::min({ v[0], v[1], v[2] }) < 0.0 || std::max({ v[0], v[1], v[2] }) > 1.0))
      {
        return bad + " (red,green,blue each in [0, 1])";
      }
      if (name == "view-up" && v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0)
      {
        return bad + " (a direction: not 0,0,0)";
      }
      entry->SetVector(target, v);
      return std::string();
    }
  }
  return bad;
}

//------------------------------------------------------------------------------
std::string Value(const Target& target, const std::string& name)
{
  const Entry* entry = FindEntry(name);
  if (!entry || (entry->ToneMapping && !target.ToneMapping))
  {
    return std::string();
  }
  switch (entry->Info.Type)
  {
    case Kind::Switch:
      return entry->Get(target) != 0.0 ? "on" : "off";
    case Kind::Choice:
    {
      const size_t index = static_cast<size_t>(entry->Get(target));
      return index < entry->Names.size() ? entry->Names[index] : std::string();
    }
    case Kind::Vector:
    {
      double v[3];
      entry->GetVector(target, v);
      return Format(v[0]) + "," + Format(v[1]) + "," + Format(v[2]);
    }
    default:
      return Format(entry->Get(target));
  }
}

//------------------------------------------------------------------------------
std::string ApplyAll(const Target& target, const Assignments& assignments)
{
  for (const auto& assignment : assignments)
  {
    const std::string problem = Apply(target, assignment.first, assignment.second);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string Check(const Assignments& assignments)
{
  Scratch scratch;
  return ApplyAll(scratch.Get(), assignments);
}
}
