// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The trace through the ice's triangles (vtkIceMapper::MaxBounces) against its CPU reference, one
// behaviour per case: every interior pixel of the GPU's picture is compared with
// vtkIceOpticsReference::TracedRefraction evaluated with vtkIceTriangleBVH::Intersect on the CPU
// (the front hit found the same way; Fresnel's equations at entry), over the DirectionTest cube
// map. The light splits at face edges and at the critical angle, so the picture has sharp
// boundaries inside the ice: each pixel's error is the smallest against the references of its
// 3x3 neighbourhood (a boundary a pixel away is not an error). Cases:
//   cube       a cube seen from a corner, rotated and scaled by its actor, 6 bounces
//   torus      a torus (non-convex: rays leave it and are not followed back in), 6 bounces
//   absorbing  the cube with absorption along the whole path, 3 bounces
//   bounces    MaxBounces 2 differs from 1 inside a cube, and 1 is the exit point's picture
//   tetrahedron  four triangles, one leaf under the root (its second child empty), 6 bounces: the
//              empty child was a node pointing back at the root, and the traversal never ended
//   core       the cube with a milky core, 6 bounces: the screen-space interior shows it along
//              the first segment, the trace on the segments after each reflection inside
//   multisampled  a coarse smooth sphere with 4 samples per pixel, 8 bounces: a pixel a triangle
//              partly covers starts its ray on the triangle's plane beyond its edge, outside the
//              next triangle; the ray met that one at once (a grid of lines along the edges)
//   cracks     the cube with three cracks, 6 bounces: the trace meets them on the segments after
//              each reflection inside (the CPU's cracks: vtkIceCrackTable, every sheet tested);
//              pixels whose eye ray meets a crack are left out (the screen-space interior draws
//              those, with its bump texture and the lights)
//   bubbles    the cube with bubbles (no core's cloud), 6 bounces: the trace shows them on the
//              segment after the first reflection inside. Pixels whose first segment stays clear
//              of the bubbles while the second, after a total reflection, crosses their middle
//              differ from the bubble-free reference; those whose two segments both stay clear
//              agree with it
//   wet-base   the cube standing in water (WetBase), 6 bounces, seen from above: its bottom shows
//              what lies below instead of mirroring the inside (the water changes a tenth of the
//              references or more)
//   antialiased  ice-render's cube (rounded edges), 6 bounces, TraceAntiAliasing on (the other
//              cases turn it off: the CPU traces one path a pixel): where the extra paths change
//              the picture, it is nearer the CPU's mean of 16 paths across each pixel than one
//              path a pixel is
#include "IceTestResources.h"
#include "IceTestUtilities.h"
#include "vtkIceAirGeometry.h"
#include "vtkIceBlockSource.h"
#include "vtkIceCrackTable.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceInteriorLook.h"
#include "vtkIceMapper.h"
#include "vtkIceOpticsReference.h"
#include "vtkIcePass.h"
#include "vtkIceProperty.h"
#include "vtkIceTriangleBVH.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkCubeSource.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPlatonicSolidSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using glm::dvec3;
namespace ref = vtkIceOpticsReference;

vtkSmartPointer<vtkPolyData> Cube()
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(1.6);
  cube->SetYLength(1.6);
  cube->SetZLength(1.6);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}

// Which way a closed surface's faces turn, as vtkIceMapper finds it: 1 counter-clockwise seen from
// outside (a positive signed volume), -1 clockwise.
int FacingOf(vtkPolyData* surface)
{
  double volume = 0.0;
  vtkCellArray* polys = surface->GetPolys();
  vtkIdType count;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    for (vtkIdType i = 2; i < count; ++i)
    {
      double a[3];
      double b[3];
      double c[3];
      surface->GetPoint(ids[0], a);
      surface->GetPoint(ids[i - 1], b);
      surface->GetPoint(ids[i], c);
      double bc[3];
      vtkMath::Cross(b, c, bc);
      volume += vtkMath::Dot(a, bc);
    }
  }
  return volume > 0.0 ? 1 : -1;
}

// Four flat faces, each its own normal: fewer triangles than a leaf holds.
vtkSmartPointer<vtkPolyData> Tetrahedron()
{
  vtkNew<vtkPlatonicSolidSource> solid;
  solid->SetSolidTypeToTetrahedron();
  vtkNew<vtkTransform> scale; // as large on the screen as the cube
  scale->Scale(1.5, 1.5, 1.5);
  vtkNew<vtkTransformFilter> scaled;
  scaled->SetInputConnection(solid->GetOutputPort());
  scaled->SetTransform(scale);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(scaled->GetOutputPort());
  normals->SplittingOn();
  normals->SetFeatureAngle(30.0);
  normals->Update();
  return normals->GetOutput();
}

// ice-render's cube (flat faces, rounded edges), as large as Cube(): behind its rounded edges the
// paths of neighbouring pixels part after a few reflections inside. VTK Ice's own source, so the
// same surface in every VTK.
vtkSmartPointer<vtkPolyData> RoundedCube()
{
  vtkNew<vtkIceBlockSource> block;
  block->SetResolution(48);
  block->SetRoundness(0.22);
  block->SetDisplacement(0.03);
  block->SetSeed(3);
  block->Update();
  double bounds[6];
  block->GetOutput()->GetBounds(bounds);
  const double extent = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  vtkNew<vtkTransform> scale;
  scale->Scale(1.6 / extent, 1.6 / extent, 1.6 / extent);
  scale->Translate(-0.5 * (bounds[0] + bounds[1]), -0.5 * (bounds[2] + bounds[3]),
    -0.5 * (bounds[4] + bounds[5]));
  vtkNew<vtkTransformFilter> scaled;
  scaled->SetInputConnection(block->GetOutputPort());
  scaled->SetTransform(scale);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(scaled->GetOutputPort());
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(triangles->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  return normals->GetOutput();
}

vtkSmartPointer<vtkPolyData> Torus()
{
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(1.0);
  torus->SetCrossSectionRadius(0.45);
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(96);
  source->SetVResolution(48);
  source->SetScalarModeToNone();
  // The source repeats its seams' points: merged, the surface is closed.
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(source->GetOutputPort());
  clean->ConvertPolysToLinesOff();
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(clean->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  return normals->GetOutput();
}

struct Scene
{
  vtkNew<vtkIceCubeMapSource> Pattern;
  vtkNew<vtkTexture> Environment;
  vtkNew<vtkIceMapper> Mapper;
  vtkNew<vtkActor> Ice;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkIcePass> Pass;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkIceTriangleBVH> WorldTree; // the surface in world coordinates, for the reference
  ref::Material Material;
  ref::TracedCore Core; // density 0: none
  ref::TracedCracks Cracks; // share 0: none
  ref::TracedWetBase WetBase; // Wet == Dry: none
  // With cracks: the cracks in world coordinates (no actor transform), to leave out the pixels
  // whose eye ray meets one.
  vtkIceCrackTable* EyeCracks = nullptr;
  // Which way the surface's triangles face, as the mapper finds it (vtkIceTriangleBVH::Intersect).
  int Orientation = 1;

  Scene(vtkPolyData* surface, const double position[3])
  {
    this->Pattern->SetPatternToDirectionTest();
    this->Pattern->SetFaceSize(256);
    this->Pattern->ConfigureTexture(this->Environment);
    this->Mapper->SetInputData(surface);
    IceTest::UseCleanOptics(this->Mapper);
    this->Mapper->SetTwoSidedMethodToExitPoint();
    this->Mapper->TraceAntiAliasingOff(); // one path a pixel, as the reference
    this->Mapper->GetIceProperty()->SetFresnelModelToDielectric();
    this->Material.DielectricFresnel = true;
    this->Ice->SetMapper(this->Mapper);
    this->Renderer->SetEnvironmentTexture(this->Environment);
    this->Renderer->AddActor(this->Ice);
    this->Renderer->SetPass(this->Pass);
    this->Window->SetSize(240, 240);
    this->Window->SetMultiSamples(0);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(position[0], position[1], position[2]);
    camera->SetViewAngle(30.0);
  }

  IceTest::Image Render()
  {
    // The reference's tree of the surface where the actor puts it.
    vtkNew<vtkTransform> placement;
    placement->SetMatrix(this->Ice->GetMatrix());
    vtkNew<vtkTransformFilter> world;
    world->SetInputData(this->Mapper->GetInput());
    world->SetTransform(placement);
    world->Update();
    vtkPolyData* placed = vtkPolyData::SafeDownCast(world->GetOutput());
    this->WorldTree->Build(placed, placed->GetPointData()->GetNormals());
    this->Renderer->ResetCameraClippingRange();
    this->Window->Render();
    return IceTest::Capture(this->Window);
  }

  // The reference colour (0..255) of pixel (x, y); false where its ray misses the ice. `seen`
  // (when given) says whether the eye ray meets a crack of EyeCracks inside the ice.
  bool Reference(int x, int y, dvec3& colour, bool* seen = nullptr) const
  {
    return this->Reference(x + 0.5, y + 0.5, colour, seen);
  }

  // The same through display point (x, y).
  bool Reference(double x, double y, dvec3& colour, bool* seen = nullptr) const
  {
    double o[3];
    double d[3];
    IceTest::PixelRay(this->Renderer, x, y, o, d);
    const dvec3 e = glm::normalize(dvec3(d[0], d[1], d[2]));
    const double direction[3] = { e.x, e.y, e.z };
    double t;
    double n[3];
    if (!this->WorldTree->Intersect(o, direction, 0.0, 1.0e30, t, n))
    {
      return false;
    }
    dvec3 nFront = glm::normalize(dvec3(n[0], n[1], n[2]));
    nFront = glm::dot(nFront, e) > 0.0 ? -nFront : nFront;
    const dvec3 position = dvec3(o[0], o[1], o[2]) + t * e;
    const IceTest::Environment environment = IceTest::PatternEnvironment(this->Pattern);
    const double epsilon = 1.0e-5 * this->WorldTree->GetDiagonal();
    auto hit = [this](const dvec3& p, const dvec3& v, double tMin, double& along, dvec3& normal,
                 dvec3& face) {
      const double origin[3] = { p.x, p.y, p.z };
      const double towards[3] = { v.x, v.y, v.z };
      double m[3];
      double f[3];
      const bool found =
        this->WorldTree->Intersect(origin, towards, tMin, 1.0e30, along, m, f, this->Orientation);
      normal = dvec3(m[0], m[1], m[2]);
      face = dvec3(f[0], f[1], f[2]);
      return found;
    };
    const dvec3 refracted = ref::TracedRefraction(e, position, nFront,
      this->Mapper->GetMaxBounces(), epsilon, this->Material, hit, environment, this->Core,
      this->Cracks, this->WetBase);
    const dvec3 reflected = environment(ref::Reflect(e, nFront));
    const double f = ref::DielectricReflectance(glm::dot(e, nFront), this->Material.RefractionRatio);
    colour = refracted + (reflected - refracted) * f;
    double chord;
    dvec3 unused;
    dvec3 unusedFace;
    const bool through = hit(position, e, epsilon, chord, unused, unusedFace);
    if (seen)
    {
      double s;
      int record;
      double edge;
      const double p[3] = { position.x, position.y, position.z };
      *seen = this->EyeCracks && through && this->EyeCracks->Nearest(p, &e.x, chord, s, record, edge);
    }
    if (this->Core.Density > 0.0 && through)
    {
      // The screen-space interior: the core along the refracted ray, to where it leaves.
      const dvec3 inside = ref::Refract(e, nFront, this->Material.RefractionRatio);
      double length;
      const bool leaves = hit(position, inside, epsilon, length, unused, unusedFace);
      const dvec3 origin = (position - this->Core.Center) * this->Core.Scale;
      const double cover = 1.0 -
        std::exp(-ref::CoreOpticalDepth(origin, inside * this->Core.Scale,
                   leaves ? length : chord, this->Core.Density) *
          ref::CoreStreaks(origin, inside * this->Core.Scale));
      colour = colour * (1.0 - cover) + this->Core.Colour * cover;
    }
    colour *= 255.0;
    return true;
  }

  // Per interior pixel (its 5x5 neighbourhood on the ice), the smallest largest-channel error
  // against the references of its 3x3 neighbourhood.
  IceTest::Stats Compare(const IceTest::Image& image) const
  {
    const int w = image.Width;
    const int h = image.Height;
    std::vector<dvec3> colours(static_cast<size_t>(w) * h);
    std::vector<bool> on(colours.size(), false);
    std::vector<bool> seen(colours.size(), false);
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        bool crack = false;
        on[y * w + x] = this->Reference(x, y, colours[y * w + x], &crack);
        seen[y * w + x] = crack;
      }
    }
    std::vector<double> errors;
    for (int y = 2; y < h - 2; ++y)
    {
      for (int x = 2; x < w - 2; ++x)
      {
        bool interior = true;
        for (int dy = -2; dy <= 2 && interior; ++dy)
        {
          for (int dx = -2; dx <= 2 && interior; ++dx)
          {
            interior = on[(y + dy) * w + x + dx] &&
              !(std::abs(dx) <= 1 && std::abs(dy) <= 1 && seen[(y + dy) * w + x + dx]);
          }
        }
        if (!interior)
        {
          continue;
        }
        double best = 255.0;
        for (int dy = -1; dy <= 1; ++dy)
        {
          for (int dx = -1; dx <= 1; ++dx)
          {
            const dvec3& c = colours[(y + dy) * w + x + dx];
            double worst = 0.0;
            for (int k = 0; k < 3; ++k)
            {
              worst = std::max(worst, std::abs(image.At(x, y)[k] - std::min(255.0, c[k])));
            }
            best = std::min(best, worst);
          }
        }
        errors.push_back(best);
      }
    }
    return IceTest::Summarize(errors);
  }
};

bool AgainstReference(const std::string& name, vtkPolyData* surface, const double camera[3],
  int bounces, bool transformed, bool absorbing, bool core = false, int orientation = 1)
{
  Scene scene(surface, camera);
  scene.Orientation = orientation;
  scene.Mapper->SetMaxBounces(bounces);
  if (core)
  {
    const double radius = 0.6;
    const double milkiness = 0.8;
    scene.Mapper->GetIceProperty()->SetMilkyCoreRadius(radius);
    scene.Mapper->GetIceProperty()->SetMilkiness(milkiness);
    double bounds[6];
    surface->GetBounds(bounds);
    double centre[3];
    double scale[3];
    vtkIceInteriorLook::CoreFrame(bounds, radius, centre, scale);
    scene.Core.Center = dvec3(centre[0], centre[1], centre[2]);
    scene.Core.Scale = dvec3(scale[0], scale[1], scale[2]);
    scene.Core.Density = vtkIceInteriorLook::CoreDensity(milkiness);
    scene.Core.Colour = dvec3(vtkIceInteriorLook::CoreColour[0],
      vtkIceInteriorLook::CoreColour[1], vtkIceInteriorLook::CoreColour[2]);
  }
  if (transformed)
  {
    scene.Ice->RotateZ(20.0);
    scene.Ice->SetScale(1.0, 0.8, 1.1);
  }
  if (absorbing)
  {
    const double colour[3] = { 0.5, 0.8, 0.95 };
    scene.Mapper->GetIceProperty()->SetAttenuationColor(colour);
    scene.Mapper->GetIceProperty()->SetAttenuationDistance(1.0);
    scene.Material.AttenuationColor = dvec3(0.5, 0.8, 0.95);
    scene.Material.InverseAttenuationDistance = 1.0;
  }
  const IceTest::Image image = scene.Render();
  bool ok =
    IceTest::Expect(IceTest::TakeGLErrors(scene.Window).empty(), name + ": no OpenGL error");
  ok = IceTest::ReportReference(
         name + ", " + std::to_string(bounces) + " bounces, against its CPU reference",
         scene.Compare(image), 10000) &&
    ok;
  return ok;
}

// ice-render's sphere: about 960 triangles, smooth normals.
vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(17);
  sphere->Update();
  return sphere->GetOutput();
}

bool Multisampled()
{
  const double camera[3] = { 0.4, 0.9, 4.2 };
  Scene scene(Sphere(), camera);
  scene.Window->SetMultiSamples(4);
  scene.Mapper->SetMaxBounces(8);
  const IceTest::Image image = scene.Render();
  bool ok = IceTest::Expect(
    IceTest::TakeGLErrors(scene.Window).empty(), "multisampled sphere: no OpenGL error");
  const std::string name = "multisampled sphere, 8 bounces, against its CPU reference";
  return IceTest::ReportReference(name, scene.Compare(image), 10000) && ok;
}

bool Cracks()
{
  const double camera[3] = { 2.6, 2.2, 2.9 };
  vtkSmartPointer<vtkPolyData> cube = Cube();
  Scene scene(cube, camera);
  scene.Mapper->SetMaxBounces(6);
  vtkIceProperty* look = scene.Mapper->GetIceProperty();
  look->SetNumberOfCracks(3);
  double bounds[6];
  cube->GetBounds(bounds);
  vtkNew<vtkIceCrackTable> table;
  table->Build(look->GetCrackSeed(), look->GetNumberOfCracks(), bounds);
  scene.EyeCracks = table;
  scene.Cracks.Share = look->GetCrackIntensity() * look->GetCrackReflection();
  scene.Cracks.Edge = vtkIceInteriorLook::CrackEdge;
  scene.Cracks.EdgeWidth = vtkIceInteriorLook::CrackEdgeWidth;
  scene.Cracks.Colour = dvec3(vtkIceInteriorLook::CoreColour[0],
    vtkIceInteriorLook::CoreColour[1], vtkIceInteriorLook::CoreColour[2]);
  scene.Cracks.Nearest = [&table](const dvec3& p, const dvec3& d, double sEnd, double& s,
                           dvec3& n, double& edge) {
    const double o[3] = { p.x, p.y, p.z };
    const double v[3] = { d.x, d.y, d.z };
    int record;
    if (!table->Nearest(o, v, sEnd, s, record, edge))
    {
      return false;
    }
    double normal[3];
    table->Normal(record, o, v, s, normal);
    n = dvec3(normal[0], normal[1], normal[2]);
    return true;
  };
  const IceTest::Image image = scene.Render();
  bool ok =
    IceTest::Expect(IceTest::TakeGLErrors(scene.Window).empty(), "cracked cube: no OpenGL error");
  // The case means something only where the traced cracks change the reference.
  size_t changed = 0;
  size_t compared = 0;
  ref::TracedCracks none;
  for (int y = 0; y < image.Height; y += 2)
  {
    for (int x = 0; x < image.Width; x += 2)
    {
      dvec3 with;
      dvec3 without;
      bool seen = false;
      if (!scene.Reference(x, y, with, &seen) || seen)
      {
        continue;
      }
      std::swap(scene.Cracks, none);
      scene.Reference(x, y, without);
      std::swap(scene.Cracks, none);
      ++compared;
      changed += glm::length(with - without) > 8.0 ? 1 : 0;
    }
  }
  ok = IceTest::Expect(changed > compared / 20,
         "cracked cube: the traced cracks change " + std::to_string(changed) + " of " +
           std::to_string(compared) + " sampled references without a crack on the eye ray") &&
    ok;
  return IceTest::ReportReference("cracked cube, 6 bounces, against its CPU reference",
           scene.Compare(image), 3000) &&
    ok;
}

// The closest a segment p + s d, s in [0, length], comes to the centre of the frame where the
// bubbles' ball has radius 1 (vtkIceInteriorLook::CoreFrame).
double Closest(const dvec3& p, const dvec3& d, double length, const dvec3& centre, const dvec3& scale)
{
  const dvec3 u = (p - centre) * scale;
  const dvec3 du = d * scale;
  const double s = std::clamp(-glm::dot(u, du) / std::max(glm::dot(du, du), 1.0e-30), 0.0, length);
  return glm::length(u + s * du);
}

// Where pixel (x, y)'s eye ray e enters the ice (entry, the front normal facing it) and its
// chord through the ice to the next face.
struct EyeEntry
{
  dvec3 E;
  dvec3 Entry;
  dvec3 Front;
  double Chord = 0.0;
  bool Through = false;
};

EyeEntry Enter(Scene& scene, int x, int y, double epsilon)
{
  EyeEntry eye;
  double o[3];
  double v[3];
  IceTest::PixelRay(scene.Renderer, x, y, o, v);
  eye.E = glm::normalize(dvec3(v[0], v[1], v[2]));
  double t;
  double n[3];
  double f[3];
  scene.WorldTree->Intersect(o, &eye.E.x, 0.0, 1.0e30, t, n);
  eye.Front = glm::normalize(dvec3(n[0], n[1], n[2]));
  eye.Front = glm::dot(eye.Front, eye.E) > 0.0 ? -eye.Front : eye.Front;
  eye.Entry = dvec3(o[0], o[1], o[2]) + t * eye.E;
  eye.Through = scene.WorldTree->Intersect(
    &eye.Entry.x, &eye.E.x, epsilon, 1.0e30, eye.Chord, n, f, scene.Orientation);
  return eye;
}

// What a pixel's path shows of a part of the interior seen along the trace (TracedPart).
enum class Seen
{
  Other,    // left out
  Crossing, // only the trace can show the part: the picture must differ from the reference
  Clear     // the path misses it: the picture must be the part-free reference
};

// Renders `scene` (whose CPU reference leaves the part out) and holds it to the reference pixel
// by pixel as `classify` sorts the pixels: of the Crossing ones more than 1/`share` differ by
// more than 16/255, the Clear ones agree within 1.5/255 on average; at least 300 of each.
bool TracedPart(Scene& scene, const std::string& name, int share, const std::string& crossingWhat,
  const std::string& clearWhat,
  const std::function<Seen(const EyeEntry& eye, double epsilon)>& classify)
{
  const IceTest::Image image = scene.Render();
  bool ok =
    IceTest::Expect(IceTest::TakeGLErrors(scene.Window).empty(), name + ": no OpenGL error");
  const double epsilon = 1.0e-5 * scene.WorldTree->GetDiagonal();
  size_t crossing = 0;
  size_t differing = 0;
  std::vector<double> clearErrors;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      dvec3 reference;
      if (!scene.Reference(x, y, reference))
      {
        continue;
      }
      const Seen seen = classify(Enter(scene, x, y, epsilon), epsilon);
      double change = 0.0;
      for (int i = 0; i < 3; ++i)
      {
        change = std::max(change, std::abs(image.At(x, y)[i] - std::min(255.0, reference[i])));
      }
      if (seen == Seen::Crossing)
      {
        ++crossing;
        differing += change > 16.0 ? 1 : 0;
      }
      else if (seen == Seen::Clear)
      {
        clearErrors.push_back(change);
      }
    }
  }
  ok = IceTest::Expect(crossing > 300 && differing > crossing / share,
         name + ": " + std::to_string(differing) + " of the " + std::to_string(crossing) +
           " pixels " + crossingWhat) &&
    ok;
  const IceTest::Stats clear = IceTest::Summarize(clearErrors);
  return IceTest::Expect(clearErrors.size() > 300 && clear.Mean < 1.5,
           name + ": the " + std::to_string(clearErrors.size()) + " pixels " + clearWhat +
             ": mean " + std::to_string(clear.Mean) + "/255") &&
    ok;
}

// The bubbles along the traced path: pixels whose second segment alone, after a total
// reflection, crosses the bubbles' middle show them; those whose two segments stay clear of them
// are the bubble-free reference.
bool Bubbles()
{
  const double camera[3] = { 2.6, 2.2, 2.9 };
  vtkSmartPointer<vtkPolyData> cube = Cube();
  Scene scene(cube, camera);
  scene.Mapper->SetMaxBounces(6);
  vtkIceProperty* look = scene.Mapper->GetIceProperty();
  look->SetBubbleDensity(1.0);
  look->SetMilkiness(0.0);
  look->SetMilkyCoreRadius(0.0); // the bubbles gather in a core of their own
  double bounds[6];
  cube->GetBounds(bounds);
  double c[3];
  double k[3];
  vtkIceInteriorLook::CoreFrame(bounds, vtkIceInteriorLook::BubbleCoreRadius, c, k);
  const dvec3 centre(c[0], c[1], c[2]);
  const dvec3 scale(k[0], k[1], k[2]);
  const double eta = scene.Material.RefractionRatio;
  return TracedPart(scene, "bubbly cube", 5,
    "whose second segment alone crosses the bubbles' middle show them",
    "whose two segments stay clear of them agree with the bubble-free reference",
    [&](const EyeEntry& eye, double epsilon) {
      // The first two segments, as the trace follows them.
      double n[3];
      double f[3];
      const dvec3 d1 = ref::Refract(eye.E, eye.Front, eta);
      double t1;
      if (!scene.WorldTree->Intersect(
            &eye.Entry.x, &d1.x, epsilon, 1.0e30, t1, n, f, scene.Orientation))
      {
        return Seen::Other;
      }
      dvec3 n1 = glm::normalize(dvec3(n[0], n[1], n[2]));
      n1 = glm::dot(n1, d1) < 0.0 ? -n1 : n1;
      const dvec3 p1 = eye.Entry + t1 * d1;
      const dvec3 d2 = ref::Reflect(d1, n1);
      double t2;
      if (!scene.WorldTree->Intersect(&p1.x, &d2.x, epsilon, 1.0e30, t2, n, f, scene.Orientation))
      {
        return Seen::Other;
      }
      // The screen-space interior shows the bubbles along the first segment over the longer of
      // the eye ray's chord and the refracted ray's path.
      const bool firstClear =
        Closest(eye.Entry, d1, std::max(t1, eye.Chord), centre, scale) > 2.0;
      const double second = Closest(p1, d2, t2, centre, scale);
      if (firstClear && second < 0.8 &&
        ref::DielectricReflectance(glm::dot(d1, n1), 1.0 / eta) >= 1.0)
      {
        return Seen::Crossing;
      }
      return firstClear && second > 2.0 ? Seen::Clear : Seen::Other;
    });
}

// Whether the segment p + s d, 0 < s < length, crosses one of the air planes (the squares
// [-1, 1]^2 of their placements; `planes` holds the inverses, world to the square's frame).
bool CrossesAir(const std::vector<vtkSmartPointer<vtkTransform>>& planes, const dvec3& p,
  const dvec3& d, double length)
{
  for (const auto& local : planes)
  {
    double a[3];
    double b[3];
    const dvec3 q = p + length * d;
    local->TransformPoint(&p.x, a);
    local->TransformPoint(&q.x, b);
    if ((a[2] > 0.0) == (b[2] > 0.0))
    {
      continue;
    }
    const double f = a[2] / (a[2] - b[2]);
    if (std::abs(a[0] + f * (b[0] - a[0])) <= 1.0 && std::abs(a[1] + f * (b[1] - a[1])) <= 1.0)
    {
      return true;
    }
  }
  return false;
}

// The air planes along the traced path: where the eye ray crosses none (the screen-space
// interior draws them there) but the segment after a total reflection inside does, the picture
// shows their bubbles; where no segment of the path crosses one, it is the air-free reference.
bool Air()
{
  const double camera[3] = { 2.6, 2.2, 2.9 };
  vtkSmartPointer<vtkPolyData> cube = Cube();
  Scene scene(cube, camera);
  const int bounces = 6;
  scene.Mapper->SetMaxBounces(bounces);
  vtkIceProperty* look = scene.Mapper->GetIceProperty();
  look->SetNumberOfAirPlanes(3); // a few, so that some paths miss them all
  look->SetMilkiness(1.0);
  double bounds[6];
  cube->GetBounds(bounds);
  std::vector<vtkSmartPointer<vtkTransform>> planes;
  for (int i = 0; i < look->GetNumberOfAirPlanes(); ++i)
  {
    planes.push_back(vtkSmartPointer<vtkTransform>::New());
    vtkIceAirGeometry::Placement(look->GetAirSeed(), i, bounds, planes.back());
    planes.back()->Inverse();
  }
  const double eta = scene.Material.RefractionRatio;
  return TracedPart(scene, "airy cube", 10,
    "whose eye ray crosses no air plane and whose segment after a total reflection does show "
    "their bubbles",
    "whose path crosses no air plane agree with the air-free reference",
    [&](const EyeEntry& eye, double epsilon) {
      if (!eye.Through || CrossesAir(planes, eye.Entry, eye.E, eye.Chord))
      {
        return Seen::Other;
      }
      // The path as the trace follows it: refracted in, then reflected at every hit.
      double n[3];
      double f[3];
      dvec3 p = eye.Entry;
      dvec3 d = ref::Refract(eye.E, eye.Front, eta);
      bool secondCrosses = false;
      bool laterCrosses = false;
      bool totalAtFirst = false;
      for (int bounce = 1; bounce <= bounces; ++bounce)
      {
        double length;
        if (!scene.WorldTree->Intersect(
              &p.x, &d.x, epsilon, 1.0e30, length, n, f, scene.Orientation))
        {
          return Seen::Other;
        }
        if (bounce > 1 && CrossesAir(planes, p, d, length))
        {
          (bounce == 2 ? secondCrosses : laterCrosses) = true;
        }
        dvec3 normal = glm::normalize(dvec3(n[0], n[1], n[2]));
        normal = glm::dot(normal, d) < 0.0 ? -normal : normal;
        if (bounce == 1)
        {
          totalAtFirst = ref::DielectricReflectance(glm::dot(d, normal), 1.0 / eta) >= 1.0;
        }
        p += length * d;
        d = ref::Reflect(d, normal);
      }
      if (secondCrosses && totalAtFirst)
      {
        return Seen::Crossing;
      }
      return !secondCrosses && !laterCrosses ? Seen::Clear : Seen::Other;
    });
}

bool AntiAliased()
{
  const double camera[3] = { 2.6, 2.2, 2.9 };
  vtkSmartPointer<vtkPolyData> cube = RoundedCube();
  Scene scene(cube, camera);
  scene.Orientation = FacingOf(cube);
  scene.Mapper->SetMaxBounces(6);
  const IceTest::Image single = scene.Render();
  scene.Mapper->TraceAntiAliasingOn();
  const IceTest::Image averaged = scene.Render();
  bool ok =
    IceTest::Expect(IceTest::TakeGLErrors(scene.Window).empty(), "antialiased rounded cube: no OpenGL error");
  // Where the extra paths changed a pixel (by more than 2/255 in a channel), the CPU's mean over
  // a 4 x 4 grid across it, the whole 16 on the ice.
  double singleError = 0.0;
  double averagedError = 0.0;
  size_t pixels = 0;
  for (int y = 0; y < single.Height; ++y)
  {
    for (int x = 0; x < single.Width; ++x)
    {
      double change = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        change = std::max(
          change, std::abs(static_cast<double>(single.At(x, y)[k]) - averaged.At(x, y)[k]));
      }
      if (change <= 2.0)
      {
        continue;
      }
      dvec3 mean(0.0);
      bool on = true;
      for (int i = 0; i < 16 && on; ++i)
      {
        dvec3 colour;
        on = scene.Reference(x + (i % 4 + 0.5) / 4.0, y + (i / 4 + 0.5) / 4.0, colour);
        mean += glm::min(colour, dvec3(255.0)) / 16.0;
      }
      if (!on)
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        singleError += std::abs(single.At(x, y)[k] - mean[k]) / 3.0;
        averagedError += std::abs(averaged.At(x, y)[k] - mean[k]) / 3.0;
      }
      ++pixels;
    }
  }
  const double n = static_cast<double>(std::max<size_t>(pixels, 1));
  ok = IceTest::Expect(pixels > 500,
         "antialiased rounded cube: the extra paths change " + std::to_string(pixels) + " pixels") &&
    ok;
  return IceTest::Expect(averagedError < 0.6 * singleError,
           "antialiased rounded cube: against the CPU's mean of 16 paths a pixel there, " +
             std::to_string(averagedError / n) + "/255 with the extra paths, " +
             std::to_string(singleError / n) + "/255 with one path") &&
    ok;
}

// The cube standing in water (WetBase): wet up to 6 % of its height, dry above 10 %, the
// cube's bottom face among it. Seen from above, the light inside meets the bottom at glancing
// angles: dry, it reflects totally; wet, most of it leaves into the water.
bool WetBase()
{
  const double camera[3] = { 2.2, 2.8, 3.0 };
  Scene scene(Cube(), camera);
  scene.Mapper->SetMaxBounces(6);
  scene.Mapper->WetBaseOn();
  scene.WetBase.Wet = -0.8 + 0.06 * 1.6;
  scene.WetBase.Dry = -0.8 + 0.1 * 1.6;
  const IceTest::Image image = scene.Render();
  bool ok =
    IceTest::Expect(IceTest::TakeGLErrors(scene.Window).empty(), "wet cube: no OpenGL error");
  // The case means something only where the water changes the reference.
  int changed = 0;
  int compared = 0;
  for (int y = 0; y < image.Height; y += 4)
  {
    for (int x = 0; x < image.Width; x += 4)
    {
      dvec3 wet;
      if (!scene.Reference(x, y, wet))
      {
        continue;
      }
      ++compared;
      const ref::TracedWetBase base = scene.WetBase;
      scene.WetBase = ref::TracedWetBase();
      dvec3 dry;
      scene.Reference(x, y, dry);
      scene.WetBase = base;
      const dvec3 difference = glm::abs(wet - dry);
      changed += std::max({ difference.x, difference.y, difference.z }) > 10.0 ? 1 : 0;
    }
  }
  ok = IceTest::Expect(changed > compared / 10,
         "wet cube: the water under the base changes " + std::to_string(changed) + " of " +
           std::to_string(compared) + " sampled references by more than 10/255") &&
    ok;
  return IceTest::ReportReference(
           "wet cube, 6 bounces, against its CPU reference", scene.Compare(image), 10000) &&
    ok;
}

bool Bounces()
{
  const double camera[3] = { 2.6, 2.2, 2.9 };
  Scene scene(Cube(), camera);
  const IceTest::Image exitPoint = scene.Render();
  scene.Mapper->SetMaxBounces(1);
  const IceTest::Image one = scene.Render();
  scene.Mapper->SetMaxBounces(2);
  const IceTest::Image two = scene.Render();
  const size_t same = IceTest::CountDiffering(exitPoint, one, 0);
  const size_t changed = IceTest::CountDiffering(one, two, 8);
  bool ok = IceTest::Expect(
    same == 0, "MaxBounces 1 is the exit point's picture (" + std::to_string(same) + " differ)");
  ok = IceTest::Expect(changed > 5000,
         "MaxBounces 2 follows the light reflected inside the cube (" + std::to_string(changed) +
           " pixels change by more than 8/255)") &&
    ok;
  return ok;
}
}

int TestIceTrace(int argc, char* argv[])
{
  const double corner[3] = { 2.6, 2.2, 2.9 };
  const double above[3] = { 0.0, 2.6, 3.6 };
  return IceTest::RunCases("TestIceTrace", argc, argv,
    { { "cube", [&] { return AgainstReference("cube", Cube(), corner, 6, true, false); } },
      // The torus' seam joins faces of opposite orders (the mapper skips nothing); which way the
      // normals filter turns the tetrahedron's faces depends on VTK's version.
      { "torus",
        [&] { return AgainstReference("torus", Torus(), above, 6, false, false, false, 0); } },
      { "absorbing",
        [&] { return AgainstReference("absorbing cube", Cube(), corner, 3, false, true); } },
      { "bounces", Bounces },
      { "tetrahedron",
        [&] {
          vtkSmartPointer<vtkPolyData> solid = Tetrahedron();
          return AgainstReference(
            "tetrahedron", solid, corner, 6, false, false, false, FacingOf(solid));
        } },
      { "core",
        [&] {
          return AgainstReference("cube with a milky core", Cube(), corner, 6, false, false, true);
        } },
      { "multisampled", Multisampled }, { "cracks", Cracks }, { "bubbles", Bubbles },
      { "air", Air }, { "wet-base", WetBase },
      { "antialiased", AntiAliased } });
}
