// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The optics' GLSL functions run on the GPU against their CPU mirrors (vtkIceOpticsReference.h)
// over a sweep of their arguments, each written by a full-screen quad into a float texture and read
// back: iceCrackReflectance (two indices, both signs of the cosine), iceFresnel, iceTransmittance,
// iceRefractionSpread, iceMasking, iceRoughInterface, iceCoreStreaks and its iceLatticeNoise
// (vtkIceOptics.glsl), iceGgxDistribution
// (vtkIcePrefilterFS.glsl). Agreement within float rounding: relative 1e-4 (absolute 1e-6 near 0;
// iceRoughInterface from inside 1e-3, see there).
#include "IceTestUtilities.h"
#include "vtkIceVTKCompat.h" // for the OpenGL loader

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
constexpr int Samples = 256;

std::string ReadSnippet(const std::string& name)
{
  // The source tree's GLSL files; VTKICE_GLSL_DIR names them where the build was moved to
  // (.ci/gpu-run.sh runs this test on another machine).
  const char* directory = std::getenv("VTKICE_GLSL_DIR");
  std::ifstream file(std::string(directory ? directory : VTKICE_GLSL_DIR) + "/" + name);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The section "//ICE::Dec" of a snippet (to the next section), or the whole text without one.
std::string Declarations(const std::string& snippet)
{
  const std::string marker = "//ICE::Dec\n";
  const std::string::size_type begin = snippet.find(marker);
  if (begin == std::string::npos)
  {
    return snippet;
  }
  const std::string::size_type start = begin + marker.size();
  return snippet.substr(start, snippet.find("//ICE::", start) - start);
}

// Rows of the texture: what the GPU writes (GLSL of x in (0, 1)) and its CPU mirror.
struct Row
{
  std::string Name;
  std::string Glsl; // a vec4 of x
  std::function<std::array<double, 4>(double)> Reference;
  double Tolerance = 1.0e-4; // relative
};
}

int TestIceOpticsFunctions(int, char*[])
{
  namespace ref = vtkIceOpticsReference;
  const ref::Vec3 n(0.0, 0.0, 1.0);
  auto eyeAt = [](double x) { return glm::normalize(ref::Vec3(std::sqrt(1.0 - x * x), 0.0, -x)); };
  const std::vector<Row> rows = {
    { "iceCrackReflectance",
      "vec4(iceCrackReflectance(x, 1.31), iceCrackReflectance(x, 1.5), "
      "iceCrackReflectance(-x, 1.31), iceCrackReflectance(x, 1.0))",
      [](double x) {
        return std::array<double, 4>{ ref::CrackReflectance(x, 1.31), ref::CrackReflectance(x, 1.5),
          ref::CrackReflectance(-x, 1.31), ref::CrackReflectance(x, 1.0) };
      } },
    { "iceDielectricReflectance",
      "vec4(iceDielectricReflectance(x, 1.0 / 1.31), iceDielectricReflectance(x, 1.31), "
      "iceDielectricReflectance(-x, 1.0 / 1.5), iceDielectricReflectance(x, 1.0))",
      [](double x) {
        return std::array<double, 4>{ ref::DielectricReflectance(x, 1.0 / 1.31),
          ref::DielectricReflectance(x, 1.31), ref::DielectricReflectance(-x, 1.0 / 1.5),
          ref::DielectricReflectance(x, 1.0) };
      } },
    { "iceFresnel",
      "vec4(iceFresnel(normalize(vec3(sqrt(1.0 - x * x), 0.0, -x)), vec3(0.0, 0.0, 1.0), 3.0), "
      "iceFresnel(normalize(vec3(sqrt(1.0 - x * x), 0.0, -x)), vec3(0.0, 0.0, 1.0), 5.0), 0.0, "
      "0.0)",
      [&](double x) {
        return std::array<double, 4>{ ref::Fresnel(eyeAt(x), n, 3.0),
          ref::Fresnel(eyeAt(x), n, 5.0), 0.0, 0.0 };
      } },
    { "iceTransmittance", "vec4(iceTransmittance(4.0 * x, vec3(0.3, 0.6, 0.9), 1.0 / 1.5), 0.0)",
      [](double x) {
        const ref::Vec3 t = ref::Transmittance(4.0 * x, ref::Vec3(0.3, 0.6, 0.9), 1.0 / 1.5);
        return std::array<double, 4>{ t[0], t[1], t[2], 0.0 };
      } },
    { "iceRefractionSpread",
      "vec4(iceRefractionSpread(-x, -sqrt(1.0 - (1.0 - x * x) / (1.31 * 1.31)), 1.0 / 1.31), "
      "iceRefractionSpread(x, sqrt(max(0.0, 1.0 - 1.31 * 1.31 * (1.0 - x * x))), 1.31), "
      "iceRefractionSpread(x, -x, 1.31), 0.0)",
      [](double x) {
        return std::array<double, 4>{
          ref::RefractionSpread(-x, -std::sqrt(1.0 - (1.0 - x * x) / (1.31 * 1.31)), 1.0 / 1.31),
          ref::RefractionSpread(
            x, std::sqrt(std::max(0.0, 1.0 - 1.31 * 1.31 * (1.0 - x * x))), 1.31),
          ref::RefractionSpread(x, -x, 1.31), 0.0 };
      } },
    { "iceMasking", "vec4(iceMasking(x, 0.09), iceMasking(-x, 0.36), iceMasking(x, 1.0), 0.0)",
      [](double x) {
        return std::array<double, 4>{ ref::Masking(x, 0.09), ref::Masking(-x, 0.36),
          ref::Masking(x, 1.0), 0.0 };
      } },
    { "iceRoughInterface",
      "vec4(iceRoughInterface(x, 1.0 / 1.31, 0.09), iceRoughInterface(-x, 1.0 / 1.31, 0.36))",
      [](double x) {
        const std::pair<double, double> a = ref::RoughInterface(x, 1.0 / 1.31, 0.09);
        const std::pair<double, double> b = ref::RoughInterface(-x, 1.0 / 1.31, 0.36);
        return std::array<double, 4>{ a.first, a.second, b.first, b.second };
      } },
    { "iceRoughInterface, from inside",
      "vec4(iceRoughInterface(x, 1.31, 0.09), iceRoughInterface(x, 1.31, 0.36))",
      [](double x) {
        const std::pair<double, double> a = ref::RoughInterface(x, 1.31, 0.09);
        const std::pair<double, double> b = ref::RoughInterface(x, 1.31, 0.36);
        return std::array<double, 4>{ a.first, a.second, b.first, b.second };
      },
      // Near the critical angle a facet's transmitted cosine is the square root of a difference
      // near 0 and its masking is linear in it: float's rounding of the facet's cosine (1e-7)
      // grows there to about 2e-4 of the share.
      1.0e-3 },
    { "iceCoreStreaks",
      "vec4(iceCoreStreaks(vec3(2.0 * x - 1.0, 0.3, -1.0), vec3(0.1, 0.2, 1.0)), "
      "iceCoreStreaks(vec3(0.5, 1.6 * x - 0.8, 0.7 * x), vec3(-0.6, 0.0, 0.8)), "
      "iceLatticeNoise(vec3(9.0 * x - 3.0, 2.5, -1.25)), "
      "iceLatticeNoise(vec3(0.75, 13.0 * x - 6.5, 4.0 * x)))",
      [](double x) {
        return std::array<double, 4>{
          ref::CoreStreaks(ref::Vec3(2.0 * x - 1.0, 0.3, -1.0), ref::Vec3(0.1, 0.2, 1.0)),
          ref::CoreStreaks(ref::Vec3(0.5, 1.6 * x - 0.8, 0.7 * x), ref::Vec3(-0.6, 0.0, 0.8)),
          ref::LatticeNoise(ref::Vec3(9.0 * x - 3.0, 2.5, -1.25)),
          ref::LatticeNoise(ref::Vec3(0.75, 13.0 * x - 6.5, 4.0 * x)) };
      } },
    { "iceGgxDistribution",
      "vec4(iceGgxDistribution(x, pow(0.25, 4.0)), iceGgxDistribution(x, pow(0.5, 4.0)), "
      "iceGgxDistribution(x, 1.0), 0.0)",
      [](double x) {
        return std::array<double, 4>{ ref::GgxDistribution(x, std::pow(0.25, 4.0)),
          ref::GgxDistribution(x, std::pow(0.5, 4.0)), ref::GgxDistribution(x, 1.0), 0.0 };
      } },
  };
  const int height = static_cast<int>(rows.size());

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(8, 8);
  // A first frame makes the context and its buffers, as an application's would.
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!IceTest::Expect(gl != nullptr, "an OpenGL render window"))
  {
    return EXIT_FAILURE;
  }
  gl->MakeCurrent();

  // texCoord spans the target, texel centres at (i + 0.5) / size.
  std::string impl = "  float x = texCoord.x;\n  int row = int(texCoord.y * " +
    std::to_string(static_cast<int>(rows.size())) + ".0);\n  vec4 value = vec4(0.0);\n";
  for (int r = 0; r < height; ++r)
  {
    impl += "  if (row == " + std::to_string(r) + ") { value = " + rows[r].Glsl + "; }\n";
  }
  impl += "  gl_FragData[0] = value;\n";
  std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl",
    ReadSnippet("vtkIceOptics.glsl") + Declarations(ReadSnippet("vtkIcePrefilterFS.glsl")));
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", impl);

  vtkNew<vtkTextureObject> target;
  target->SetContext(gl);
  target->SetInternalFormat(GL_RGBA32F);
  target->SetFormat(GL_RGBA);
  target->SetDataType(GL_FLOAT);
  target->Allocate2D(Samples, height, 4, VTK_FLOAT);
  vtkNew<vtkOpenGLFramebufferObject> framebuffer;
  framebuffer->SetContext(gl);
  vtkOpenGLState* state = gl->GetState();
  state->PushFramebufferBindings();
  framebuffer->Bind();
  framebuffer->AddColorAttachment(0, target);
  framebuffer->ActivateDrawBuffer(0);
  state->vtkglViewport(0, 0, Samples, height);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST); // the window's frame left it set to its 8 x 8
  std::vector<float> values(4 * Samples * height);
  {
    vtkOpenGLQuadHelper quad(gl, nullptr, fs.c_str(), "");
    bool ok = quad.Program != nullptr && quad.Program->GetCompiled();
    if (ok)
    {
      gl->GetShaderCache()->ReadyShaderProgram(quad.Program);
      quad.Render();
      glReadBuffer(GL_COLOR_ATTACHMENT0);
      glReadPixels(0, 0, Samples, height, GL_RGBA, GL_FLOAT, values.data());
    }
    quad.ReleaseGraphicsResources(gl);
    if (!IceTest::Expect(ok, "the functions compile on the GPU"))
    {
      state->PopFramebufferBindings();
      return EXIT_FAILURE;
    }
  }
  state->PopFramebufferBindings();
  framebuffer->ReleaseGraphicsResources(gl);
  target->ReleaseGraphicsResources(gl);

  bool ok = true;
  for (int r = 0; r < height; ++r)
  {
    double worst = 0.0;
    for (int i = 0; i < Samples; ++i)
    {
      const double x = (i + 0.5) / Samples;
      const std::array<double, 4> expected = rows[r].Reference(x);
      for (int c = 0; c < 4; ++c)
      {
        const double gpu = values[4 * (r * Samples + i) + c];
        worst =
          std::max(worst, std::abs(gpu - expected[c]) / std::max(1.0e-2, std::abs(expected[c])));
      }
    }
    ok = IceTest::Expect(worst <= rows[r].Tolerance,
           rows[r].Name + " on the GPU matches its CPU mirror (largest relative difference " +
             std::to_string(worst) + ")") &&
      ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
