// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-bench's groups: which configurations are timed against plain VTK, on which object and scene.
#include "IceBench.h"

#include "vtkIceCubeMapPass.h"
#include "vtkIceMapper.h"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace
{
using IceBench::Configuration;
using IceBench::Group;
using IceBench::Material;

Configuration Plain()
{
  Configuration c;
  c.Label = "plain VTK (Phong)";
  return c;
}

// What a VTK user can do for a closed object too (vtkIceMapper::CullHiddenBackfaces does it for
// the ice where it is safe).
Configuration PlainCulled()
{
  Configuration c = Plain();
  c.Label = "plain VTK, back faces culled";
  c.PlainBackfaceCulling = true;
  return c;
}

const int PaperPasses = vtkIceMapper::InteriorPaperPasses;
const int ScreenSpace = vtkIceMapper::InteriorScreenSpace;

Configuration Ice(
  const std::string& label, Material material, int cracks = 0, int interior = ScreenSpace)
{
  Configuration c;
  c.Label = label;
  c.Ice = material;
  c.Cracks = material == Material::FullLook ? 2 : cracks;
  c.AirPlanes = material == Material::FullLook ? 19 : 0;
  c.Interior = interior;
  return c;
}

// The ice without vtkIceMapper::CullHiddenBackfaces: what the culling saves.
Configuration EveryFace(Configuration c)
{
  c.DrawEveryFace = true;
  return c;
}

Configuration Dynamic(const std::string& label, int mode, int faceSize = 512, int facesPerFrame = 6,
  bool culling = true, bool moving = false)
{
  Configuration c = Ice(label, Material::TwoSided);
  c.CubeMap = true;
  c.UpdateMode = mode;
  c.FaceSize = faceSize;
  c.FacesPerFrame = facesPerFrame;
  c.Culling = culling;
  c.Moving = moving;
  return c;
}

std::vector<Group> DefineGroups()
{
  std::vector<Group> groups;
  const char* const objects[3] = { "sphere", "block", "teapot" };
  for (double coverage : { 0.2, 1.0 })
  {
    for (const char* object : objects)
    {
      Group g;
      const bool fifth = coverage < 0.5;
      g.Id = std::string(fifth ? "objects-" : "fullscreen-") + object;
      g.Title = std::string(object) + ", static environment, ice " +
        (fifth ? "about 1/5 of the screen" : "covering the screen");
      g.Object = object;
      g.Coverage = coverage;
      g.Quick = fifth && std::string(object) == "teapot";
      g.Configurations = { Plain(), PlainCulled(), Ice("one-sided ice", Material::OneSided),
        Ice("two-sided ice", Material::TwoSided),
        EveryFace(Ice("two-sided ice, every face drawn", Material::TwoSided)),
        Ice("two-sided ice, exit point", Material::ExitPoint),
        Ice("full look, paper passes", Material::FullLook, 2, PaperPasses),
        Ice("full look, screen space", Material::FullLook, 2, ScreenSpace) };
      groups.push_back(g);
    }
  }

  Group dynamic;
  dynamic.Id = "dynamic-teapot";
  dynamic.Title = "teapot in the landscape, ice about 1/5 of the screen";
  dynamic.Object = "teapot";
  dynamic.Landscape = true;
  dynamic.Quick = true;
  const int every = vtkIceCubeMapPass::EveryFrame;
  const int onChange = vtkIceCubeMapPass::OnChange;
  dynamic.Configurations = { Plain(), Ice("two-sided, static environment", Material::TwoSided),
    Dynamic("cube map every frame, 512", every),
    Dynamic("cube map every frame, 512, no culling", every, 512, 6, false),
    Dynamic("cube map every frame, 256", every, 256),
    Dynamic("cube map every frame, 128", every, 128),
    Dynamic("cube map on change, still scene", onChange),
    Dynamic("cube map on change, ball moving", onChange, 512, 6, true, true),
    Dynamic("cube map 1 face per frame, 512", every, 512, 1),
    Dynamic("cube map 2 faces per frame, 512", every, 512, 2),
    Dynamic("cube map 3 faces per frame, 512", every, 512, 3) };
  groups.push_back(dynamic);

  Group cracks;
  cracks.Id = "cracks-teapot";
  cracks.Title = "teapot, static environment, two-sided, ice about 1/5 of the screen";
  cracks.Object = "teapot";
  cracks.Quick = true;
  cracks.Configurations = { Plain() };
  for (int interior : { PaperPasses, ScreenSpace })
  {
    for (int n : { 0, 2, 8, 32, 128 })
    {
      cracks.Configurations.push_back(Ice(std::to_string(n) + (n == 1 ? " crack" : " cracks") +
          ", " + IceBench::InteriorName(interior),
        Material::TwoSided, n, interior));
    }
  }
  groups.push_back(cracks);

  // The trace through the ice's triangles (vtkIceMapper::MaxBounces) on the block and the
  // teapot (non-convex), clean ice.
  for (const char* object : { "block", "teapot" })
  {
    Group g;
    g.Id = std::string("bounces-") + object;
    g.Title = std::string(object) + ", static environment, exit point, ice about 1/5 of the screen";
    g.Object = object;
    g.Configurations = { Plain() };
    for (int bounces : { 1, 2, 4, 8 })
    {
      Configuration c = Ice(std::to_string(bounces) + (bounces == 1 ? " bounce" : " bounces"),
        Material::ExitPoint);
      c.Bounces = bounces;
      g.Configurations.push_back(c);
    }
    // Five cracks (the lake and glacier looks'): the screen-space interior's along the eye ray
    // alone at 1 bounce, and the trace's on every segment after a reflection inside at 8.
    for (int bounces : { 1, 8 })
    {
      Configuration c = Ice(std::to_string(bounces) + (bounces == 1 ? " bounce" : " bounces") +
          ", 5 cracks",
        Material::ExitPoint, 5);
      c.Bounces = bounces;
      g.Configurations.push_back(c);
    }
    groups.push_back(g);
  }

  // The default picture's look (the ice-cube preset) on the cube, part by part: the trace, the
  // frost, the milky core, the bubbles.
  Group look;
  look.Id = "look-cube";
  look.Title = "cube, static environment, exit point, ice about 1/5 of the screen";
  look.Object = "cube";
  look.Configurations = { Plain() };
  for (int part = 0; part < 5; ++part)
  {
    static const char* const labels[] = { "exit point", "8 bounces", "8 bounces, roughness 0.08",
      "8 bounces, roughness 0.08, milky core 0.5", "ice-cube look: + bubbles 1" };
    Configuration c = Ice(labels[part], Material::ExitPoint);
    c.Bounces = part >= 1 ? 8 : 1;
    c.Roughness = part >= 2 ? 0.08 : 0.0;
    c.MilkyCore = part >= 3 ? 0.5 : 0.0;
    c.Bubbles = part >= 4 ? 1.0 : 0.0;
    look.Configurations.push_back(c);
  }
  // What the extra paths where one a pixel aliases cost the whole look.
  Configuration single = look.Configurations.back();
  single.Label = "ice-cube look, one path a pixel (TraceAntiAliasing off)";
  single.TraceAntiAliasing = false;
  look.Configurations.push_back(single);
  groups.push_back(look);

  for (const char* size : { "1k", "10k", "100k", "1M" })
  {
    Group g;
    g.Id = std::string("triangles-") + size;
    g.Title = std::string("sphere of ") + size + " triangles, static environment, about 1/5";
    g.Object = std::string("sphere-") + size;
    g.Quick = std::string(size) == "1k" || std::string(size) == "10k";
    // The full look too: at the same coverage, whether its cost follows the triangles.
    g.Configurations = { Plain(), Ice("one-sided ice", Material::OneSided),
      Ice("two-sided ice", Material::TwoSided),
      Ice("full look, paper passes", Material::FullLook, 2, PaperPasses),
      Ice("full look, screen space", Material::FullLook, 2, ScreenSpace) };
    groups.push_back(g);
  }
  return groups;
}

// Quick mode keeps the cheap end of every scaling series.
void Shorten(Group& g)
{
  auto keep = [&](const std::function<bool(const Configuration&)>& wanted) {
    std::vector<Configuration> kept;
    for (const Configuration& c : g.Configurations)
    {
      if (c.Ice == Material::Plain || wanted(c))
      {
        kept.push_back(c);
      }
    }
    g.Configurations = kept;
  };
  if (g.Id == "dynamic-teapot")
  {
    keep([](const Configuration& c) {
      return !c.CubeMap || (c.FaceSize == 128) ||
        (c.UpdateMode == vtkIceCubeMapPass::OnChange && !c.Moving);
    });
  }
  else if (g.Id == "cracks-teapot")
  {
    keep([](const Configuration& c) { return c.Cracks <= 8; });
  }
}
}

std::vector<Group> IceBench::SelectGroups(bool quick, const std::string& only)
{
  std::vector<Group> groups;
  for (Group& g : DefineGroups())
  {
    if ((quick && !g.Quick) || (!only.empty() && g.Id.find(only) == std::string::npos))
    {
      continue;
    }
    if (quick)
    {
      Shorten(g);
    }
    groups.push_back(g);
  }
  return groups;
}

std::string IceBench::InteriorName(int interior)
{
  return interior == PaperPasses ? "paper passes" : "screen space";
}

std::string IceBench::InteriorId(int interior)
{
  std::string id = InteriorName(interior);
  std::replace(id.begin(), id.end(), ' ', '-');
  return id;
}
