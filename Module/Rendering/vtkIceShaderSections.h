// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Splits the module's .glsl snippets into the parts injected at VTK's shader tags.
// A snippet holds a "//ICE::Dec" section (declarations) and an "//ICE::Impl" section (code).
#ifndef vtkIceShaderSections_h
#define vtkIceShaderSections_h

#include "vtkShaderProgram.h" // for Substitute

#include <string>
#include <utility>
#include <vector>

// The ice code of one surface program, by where it goes in VTK's shaders.
// vtkIceWorldSpaceMapper::ReplaceShaderValues inserts it, in one place and one order: the
// world-space part first, then what its subclass appended.
struct vtkIceShaderParts
{
  std::string VertexDeclarations;   // after //VTK::Normal::Dec
  std::string VertexImpl;           // after //VTK::Light::Impl
  std::string FragmentExtensions;   // after //VTK::System::Dec (the #version line): #extension
  std::string FragmentDeclarations; // after //VTK::Normal::Dec
  std::string FragmentNormalImpl;   // after //VTK::Normal::Impl: before VTK's lighting
  std::string FragmentImpl;         // after //VTK::Light::Impl: after it
  std::string FragmentFunctions;    // before main(): after all of VTK's declarations
  // Hooks of the snippets (//ICEHOOK::Name) and the code replacing them. Hooks left empty are
  // comments; a render pass may fill them in its PostReplaceShaderValues.
  std::vector<std::pair<std::string, std::string>> Hooks;
};

namespace vtkIceShaderSections
{
// The text of section `name` ("Dec" or "Impl") of `snippet`, up to the next section marker.
inline std::string Get(const std::string& snippet, const std::string& name)
{
  const std::string marker = "//ICE::" + name + "\n";
  std::string::size_type begin = snippet.find(marker);
  if (begin == std::string::npos)
  {
    return std::string();
  }
  begin += marker.size();
  std::string::size_type end = snippet.find("//ICE::", begin);
  return snippet.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// Adds global declarations to a complete shader source, just before main(). False when the
// source has no main().
inline bool InsertDeclarations(std::string& source, const std::string& declarations)
{
  const std::string::size_type main = source.find("void main()");
  if (main != std::string::npos)
  {
    source.insert(main, declarations);
  }
  return main != std::string::npos;
}

// Inserts `code` right after VTK's `tag` in `source`, keeping the tag so VTK still expands it
// before our code. False when VTK's source has no such tag (nothing is inserted).
inline bool InsertAfterTag(std::string& source, const std::string& tag, const std::string& code)
{
  return vtkShaderProgram::Substitute(source, tag, tag + "\n" + code);
}

// Fills hook `name` (//ICEHOOK::name) of `source` with `code`.
inline void FillHook(std::string& source, const std::string& name, const std::string& code)
{
  vtkShaderProgram::Substitute(source, "//ICEHOOK::" + name, code);
}

// Inserts `parts` into the vertex and fragment sources. Returns the places VTK's sources lack
// (e.g. "//VTK::Light::Impl (fragment)"), empty when every part found its place: a VTK whose
// shaders lost one needs this code updated.
inline std::string Insert(const vtkIceShaderParts& parts, std::string& vs, std::string& fs)
{
  std::string missing;
  auto note = [&missing](bool found, const char* what) {
    missing += found ? "" : std::string(missing.empty() ? "" : ", ") + what;
  };
  note(InsertAfterTag(vs, "//VTK::Normal::Dec", parts.VertexDeclarations),
    "//VTK::Normal::Dec (vertex)");
  note(InsertAfterTag(vs, "//VTK::Light::Impl", parts.VertexImpl), "//VTK::Light::Impl (vertex)");
  if (!parts.FragmentExtensions.empty())
  {
    note(InsertAfterTag(fs, "//VTK::System::Dec", parts.FragmentExtensions),
      "//VTK::System::Dec (fragment)");
  }
  note(InsertAfterTag(fs, "//VTK::Normal::Dec", parts.FragmentDeclarations),
    "//VTK::Normal::Dec (fragment)");
  note(InsertAfterTag(fs, "//VTK::Normal::Impl", parts.FragmentNormalImpl),
    "//VTK::Normal::Impl (fragment)");
  note(
    InsertAfterTag(fs, "//VTK::Light::Impl", parts.FragmentImpl), "//VTK::Light::Impl (fragment)");
  note(InsertDeclarations(fs, parts.FragmentFunctions), "void main() (fragment)");
  for (const auto& hook : parts.Hooks)
  {
    FillHook(fs, hook.first, hook.second);
  }
  return missing;
}
}

#endif
