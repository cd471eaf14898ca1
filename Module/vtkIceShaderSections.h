// Splits the module's .glsl snippets into the parts injected at VTK's shader tags.
// A snippet holds a "//ICE::Dec" section (declarations) and an "//ICE::Impl" section (code).
#ifndef vtkIceShaderSections_h
#define vtkIceShaderSections_h

#include "vtkShaderProgram.h" // for Substitute

#include <string>

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

// Adds global declarations to a complete shader source, just before main().
inline void InsertDeclarations(std::string& source, const std::string& declarations)
{
  const std::string::size_type main = source.find("void main()");
  if (main != std::string::npos)
  {
    source.insert(main, declarations);
  }
}

// Inserts `code` right after VTK's `tag` in `source`, keeping the tag so VTK still expands it
// before our code.
inline void InsertAfterTag(std::string& source, const std::string& tag, const std::string& code)
{
  vtkShaderProgram::Substitute(source, tag, tag + "\n" + code);
}
}

#endif
