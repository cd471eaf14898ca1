// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's targets (issue 8, item 4: llvmpipe, ice about 1/5 of 1024x768, ratio to plain VTK):
// which configuration each target compares and whether it is met.
#include "IceBench.h"

#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"

#include "vtkNew.h"

#include <functional>
#include <string>
#include <vector>

namespace
{
// The targets hold for the interior method a user gets: the mapper's default.
int Default()
{
  vtkNew<vtkIceMapper> mapper;
  return mapper->GetInteriorMethod();
}

using IceBench::Configuration;
using IceBench::Group;
using IceBench::Material;

const Configuration* Find(const std::vector<Group>& groups, const std::string& id,
  const std::function<bool(const Configuration&)>& wanted)
{
  for (const Group& g : groups)
  {
    if (g.Id != id)
    {
      continue;
    }
    for (const Configuration& c : g.Configurations)
    {
      if (wanted(c) && !c.Times.empty())
      {
        return &c;
      }
    }
  }
  return nullptr;
}
}

std::vector<IceBench::Target> IceBench::EvaluateTargets(const std::vector<Group>& groups)
{
  std::vector<IceBench::Target> targets;
  auto ratio = [&](const std::string& name, const std::string& limit, double bound,
                 const Configuration* c) {
    IceBench::Target t;
    t.Name = name;
    t.Limit = limit;
    t.Bound = bound;
    t.Measured = c != nullptr;
    t.Value = c ? c->Ratio : 0.0;
    t.Met = t.Measured && t.Value <= bound;
    targets.push_back(t);
  };
  for (const char* object : { "sphere", "block", "teapot" })
  {
    const std::string id = std::string("objects-") + object;
    ratio(std::string("static environment, two-sided (") + object + ")", "<= 1.3x", 1.3,
      Find(groups, id, [](const Configuration& c) { return c.Ice == Material::TwoSided; }));
  }
  auto fullLook = [&](const char* object) {
    return Find(groups, std::string("objects-") + object, [](const Configuration& c) {
      return c.Ice == Material::FullLook && c.Interior == Default();
    });
  };
  for (const char* object : { "sphere", "block", "teapot" })
  {
    ratio(std::string("full look, default interior (") + object + ")", "<= 1.5x", 1.5,
      fullLook(object));
  }
  // Issue 36 asked 1.5x (a GPU's figure); issue 50 asks 2.5x on llvmpipe.
  for (const char* object : { "sphere", "block", "teapot" })
  {
    ratio(std::string("full look, issue 50's bound for llvmpipe (") + object + ")", "<= 2.5x",
      2.5, fullLook(object));
  }
  ratio("dynamic cube map every frame (teapot, landscape, 512)", "<= 3x", 3.0,
    Find(groups, "dynamic-teapot", [](const Configuration& c) {
      return c.CubeMap && c.UpdateMode == vtkIceCubeMapPass::EveryFrame && c.FaceSize == 512 &&
        c.FacesPerFrame == 6 && c.Culling;
    }));
  const Configuration* two = Find(groups, "cracks-teapot",
    [](const Configuration& c) { return c.Interior == Default() && c.Cracks == 2; });
  const Configuration* many = Find(groups, "cracks-teapot",
    [](const Configuration& c) { return c.Interior == Default() && c.Cracks == 128; });
  // Issue 8 asked +25 %; issue 50 asks +50 % on llvmpipe (and +25 % on a GPU).
  for (const double bound : { 0.25, 0.5 })
  {
    IceBench::Target t;
    t.Name = bound < 0.3 ? "cracks 2 -> 128, default interior (teapot)"
                         : "cracks 2 -> 128, issue 50's bound for llvmpipe (teapot)";
    t.Limit = bound < 0.3 ? "adds <= 25 %" : "adds <= 50 %";
    t.Bound = bound;
    t.IsIncrease = true;
    t.Measured = two && many;
    t.Value = t.Measured ? many->Stats.Median / two->Stats.Median - 1.0 : 0.0;
    t.Met = t.Measured && t.Value <= t.Bound;
    targets.push_back(t);
  }
  return targets;
}
