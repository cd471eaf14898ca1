// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceModelFileChecks.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace vtkIceModelFileChecks
{
namespace
{
std::string Quote(const std::string& path)
{
  return "'" + Printable(path) + "'";
}

// vtkSTLReader's choice (vtksys::SystemTools::DetectFileType): text when fewer than 5 % of the
// first 256 bytes are outside printable ASCII, tab and line ends.
bool LooksLikeText(std::ifstream& in)
{
  char head[256];
  in.read(head, sizeof(head));
  const std::streamsize n = in.gcount();
  in.clear();
  in.seekg(0);
  if (n <= 0)
  {
    return false;
  }
  std::streamsize text = 0;
  for (std::streamsize i = 0; i < n; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(head[i]);
    text += (c >= 0x20 && c <= 0x7F) || c == '\n' || c == '\r' || c == '\t' ? 1 : 0;
  }
  return static_cast<double>(n - text) / static_cast<double>(n) < 0.05;
}

std::uint64_t FileSize(std::ifstream& in)
{
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0);
  return size < 0 ? 0 : static_cast<std::uint64_t>(size);
}

// The PLY scalar types by their names in the header; 0 for an unknown name.
int ScalarSize(const std::string& type)
{
  static const std::pair<const char*, int> types[] = { { "char", 1 }, { "int8", 1 }, { "uchar", 1 },
    { "uint8", 1 }, { "short", 2 }, { "int16", 2 }, { "ushort", 2 }, { "uint16", 2 }, { "int", 4 },
    { "int32", 4 }, { "uint", 4 }, { "uint32", 4 }, { "float", 4 }, { "float32", 4 },
    { "double", 8 }, { "float64", 8 } };
  for (const auto& t : types)
  {
    if (type == t.first)
    {
      return t.second;
    }
  }
  return 0;
}

bool IsIntegerType(const std::string& type)
{
  return type.find("float") == std::string::npos && type != "double";
}

struct Property
{
  std::string Name;
  std::string Type;      // of the value, or of the items of a list
  std::string CountType; // empty unless a list
};

struct Element
{
  std::string Name;
  std::uint64_t Count = 0;
  std::vector<Property> Properties;
};

enum class Format
{
  Ascii,
  BinaryLittle,
  BinaryBig
};

// Reads one binary scalar of PLY type `type` as a double (integer types exactly).
bool ReadBinary(std::ifstream& in, const std::string& type, Format format, double& value)
{
  const int size = ScalarSize(type);
  unsigned char bytes[8];
  if (!in.read(reinterpret_cast<char*>(bytes), size))
  {
    return false;
  }
  const bool hostLittle = [] {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }();
  if (hostLittle != (format == Format::BinaryLittle))
  {
    std::reverse(bytes, bytes + size);
  }
  auto as = [&bytes](auto v) {
    std::memcpy(&v, bytes, sizeof(v));
    return static_cast<double>(v);
  };
  const bool isSigned = type[0] != 'u';
  switch (size)
  {
    case 1:
      value = isSigned ? as(std::int8_t()) : as(std::uint8_t());
      break;
    case 2:
      value = isSigned ? as(std::int16_t()) : as(std::uint16_t());
      break;
    case 4:
      value = !IsIntegerType(type) ? as(float())
        : isSigned                 ? as(std::int32_t())
                                   : as(std::uint32_t());
      break;
    default:
      value = as(double());
      break;
  }
  return true;
}

class PlyChecker
{
public:
  explicit PlyChecker(const std::string& path)
    : Path(path)
    , In(path, std::ios::binary)
  {
  }

  std::string Check()
  {
    if (!this->In)
    {
      return "cannot open " + Quote(this->Path);
    }
    this->Size = FileSize(this->In);
    std::string problem = this->ReadHeader();
    if (!problem.empty())
    {
      return "PLY file " + Quote(this->Path) + " has a bad header: " + problem;
    }
    for (const Element& element : this->Elements)
    {
      problem =
        this->Format_ == Format::Ascii ? this->WalkAscii(element) : this->WalkBinary(element);
      if (!problem.empty())
      {
        return "PLY file " + Quote(this->Path) + " is cut off or corrupt: " + problem;
      }
    }
    return std::string();
  }

private:
  std::string ReadHeader()
  {
    std::string line;
    if (!std::getline(this->In, line) || line.compare(0, 3, "ply") != 0)
    {
      return "it does not start with 'ply'";
    }
    bool haveFormat = false;
    for (int lines = 0; std::getline(this->In, line); ++lines)
    {
      if (lines > 100000)
      {
        return "no 'end_header' in its first 100000 lines";
      }
      if (!line.empty() && line.back() == '\r')
      {
        line.pop_back();
      }
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      if (keyword == "end_header")
      {
        if (!haveFormat)
        {
          return "no 'format' line";
        }
        return std::string();
      }
      if (keyword == "format")
      {
        std::string format;
        words >> format;
        if (format == "ascii")
        {
          this->Format_ = Format::Ascii;
        }
        else if (format == "binary_little_endian")
        {
          this->Format_ = Format::BinaryLittle;
        }
        else if (format == "binary_big_endian")
        {
          this->Format_ = Format::BinaryBig;
        }
        else
        {
          return "unknown format '" + Printable(format, 40) + "'";
        }
        haveFormat = true;
      }
      else if (keyword == "element")
      {
        Element element;
        long double count = -1;
        if (!(words >> element.Name >> count) || count < 0 || count > 1e15L)
        {
          return "bad element line '" + Printable(line, 80) + "'";
        }
        element.Count = static_cast<std::uint64_t>(count);
        this->Elements.push_back(element);
      }
      else if (keyword == "property")
      {
        if (this->Elements.empty())
        {
          return "a property before any element";
        }
        Property property;
        std::string type;
        words >> type;
        if (type == "list")
        {
          words >> property.CountType >> property.Type;
          if (!ScalarSize(property.CountType) || !IsIntegerType(property.CountType))
          {
            return "bad list count type in '" + Printable(line, 80) + "'";
          }
        }
        else
        {
          property.Type = type;
        }
        if (!ScalarSize(property.Type) || !(words >> property.Name))
        {
          return "bad property line '" + Printable(line, 80) + "'";
        }
        this->Elements.back().Properties.push_back(property);
      }
      else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty())
      {
        return "unknown line '" + Printable(line, 80) + "'";
      }
    }
    return "no 'end_header'";
  }

  // The number of vertices a face's index list may name; -1 when the list holds no indices.
  double IndexLimit(const Element& element, const Property& property) const
  {
    if (element.Name != "face" ||
      (property.Name != "vertex_indices" && property.Name != "vertex_index"))
    {
      return -1;
    }
    for (const Element& e : this->Elements)
    {
      if (e.Name == "vertex")
      {
        return static_cast<double>(e.Count);
      }
    }
    return 0;
  }

  std::string Where(const Element& element, std::uint64_t index) const
  {
    std::ostringstream where;
    where << element.Name << " " << index << " of " << element.Count;
    return where.str();
  }

  std::string BadIndex(const Element& element, std::uint64_t index, double value, double limit)
  {
    std::ostringstream problem;
    problem << Where(element, index) << " names vertex " << value << " (the file has " << limit
            << " vertices)";
    return problem.str();
  }

  std::string WalkBinary(const Element& element)
  {
    const std::uint64_t left = this->Size - static_cast<std::uint64_t>(this->In.tellg());
    bool fixed = true;
    std::uint64_t fixedSize = 0;
    for (const Property& p : element.Properties)
    {
      fixed = fixed && p.CountType.empty();
      fixedSize += ScalarSize(p.Type);
    }
    if (fixed)
    {
      // One check for the whole element block; fixedSize is at most 8 per property.
      if (fixedSize != 0 && element.Count > left / fixedSize)
      {
        std::ostringstream problem;
        problem << "the header declares " << element.Count << " " << element.Name << " elements of "
                << fixedSize << " bytes, but " << left << " bytes are left";
        return problem.str();
      }
      this->In.seekg(static_cast<std::streamoff>(element.Count * fixedSize), std::ios::cur);
      return std::string();
    }
    for (std::uint64_t i = 0; i < element.Count; ++i)
    {
      for (const Property& p : element.Properties)
      {
        double count = 1;
        if (!p.CountType.empty() && !ReadBinary(this->In, p.CountType, this->Format_, count))
        {
          return "the file ends in " + Where(element, i);
        }
        const double limit = this->IndexLimit(element, p);
        const std::uint64_t items = count < 0 ? 0 : static_cast<std::uint64_t>(count);
        if (count < 0)
        {
          return Where(element, i) + " has a list of negative length";
        }
        for (std::uint64_t k = 0; k < items; ++k)
        {
          double value = 0;
          if (!ReadBinary(this->In, p.Type, this->Format_, value))
          {
            return "the file ends in " + Where(element, i);
          }
          if (limit >= 0 && (value < 0 || value >= limit))
          {
            return BadIndex(element, i, value, limit);
          }
        }
      }
    }
    return std::string();
  }

  std::string WalkAscii(const Element& element)
  {
    // vtkPLY reads one element per line and takes its values from that line alone.
    std::string line;
    for (std::uint64_t i = 0; i < element.Count; ++i)
    {
      if (!std::getline(this->In, line))
      {
        return "the file ends before " + Where(element, i);
      }
      std::istringstream words(line);
      for (const Property& p : element.Properties)
      {
        double count = 1;
        if (!p.CountType.empty() && !(words >> count))
        {
          return Where(element, i) + " has too few values";
        }
        if (count < 0 || count != static_cast<double>(static_cast<long long>(count)))
        {
          return Where(element, i) + " has a bad list length";
        }
        const double limit = this->IndexLimit(element, p);
        for (long long k = 0; k < static_cast<long long>(count); ++k)
        {
          double value = 0;
          if (!(words >> value))
          {
            return Where(element, i) + " has too few values";
          }
          if (limit >= 0 && (value < 0 || value >= limit))
          {
            return BadIndex(element, i, value, limit);
          }
        }
      }
    }
    return std::string();
  }

  std::string Path;
  std::ifstream In;
  std::uint64_t Size = 0;
  Format Format_ = Format::Ascii;
  std::vector<Element> Elements;
};
}

std::string Printable(const std::string& text, std::size_t limit)
{
  std::string out;
  for (std::size_t i = 0; i < text.size();)
  {
    if (out.size() >= limit)
    {
      return out + "...";
    }
    const unsigned char c = static_cast<unsigned char>(text[i]);
    // Valid UTF-8 sequences stay (file names may be in any language); control characters and
    // stray bytes, which could drive the terminal, do not.
    std::size_t length = c < 0x80 ? 1
      : (c >> 5) == 0x6           ? 2
      : (c >> 4) == 0xE           ? 3
      : (c >> 3) == 0x1E          ? 4
                                  : 0;
    for (std::size_t k = 1; k < length; ++k)
    {
      if (i + k >= text.size() || (static_cast<unsigned char>(text[i + k]) >> 6) != 0x2)
      {
        length = 0;
      }
    }
    if (length == 1 && (c < 0x20 || c == 0x7F))
    {
      length = 0;
    }
    if (length == 0)
    {
      out += '?';
      ++i;
      continue;
    }
    out.append(text, i, length);
    i += length;
  }
  return out;
}

std::string CheckSTL(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return "cannot open " + Quote(path);
  }
  const std::uint64_t size = FileSize(in);
  if (LooksLikeText(in))
  {
    // vtkSTLReader reports what it cannot parse; a file cut between two facets parses, so its
    // last line must be 'endsolid'.
    const std::uint64_t tail = std::min<std::uint64_t>(size, 4096);
    std::string end(static_cast<std::size_t>(tail), '\0');
    in.seekg(static_cast<std::streamoff>(size - tail));
    in.read(&end[0], static_cast<std::streamsize>(tail));
    end.erase(end.find_last_not_of(" \t\r\n") + 1);
    const std::string::size_type lineStart = end.find_last_of('\n');
    std::string last = end.substr(lineStart == std::string::npos ? 0 : lineStart + 1);
    last.erase(0, last.find_first_not_of(" \t"));
    if (last.compare(0, 8, "endsolid") != 0)
    {
      return "ASCII STL file " + Quote(path) + " does not end with 'endsolid' (cut off?)";
    }
    return std::string();
  }
  if (size < 84)
  {
    return "binary STL file " + Quote(path) + " has " + std::to_string(size) +
      " bytes, fewer than its 84-byte header";
  }
  unsigned char countBytes[4];
  in.seekg(80);
  in.read(reinterpret_cast<char*>(countBytes), 4);
  const std::uint64_t count = countBytes[0] | (countBytes[1] << 8) | (countBytes[2] << 16) |
    (static_cast<std::uint64_t>(countBytes[3]) << 24);
  // A count of 0 is common from exporters that never fill it in; the size must still fit.
  const bool fits = (size - 84) % 50 == 0 && (count == 0 || count == (size - 84) / 50);
  if (!fits)
  {
    return "binary STL file " + Quote(path) + " does not match its header: it announces " +
      std::to_string(count) + " triangles (" + std::to_string(84 + 50 * count) +
      " bytes) but has " + std::to_string(size) + " bytes (cut off, or not an STL file)";
  }
  return std::string();
}

std::string CheckPLY(const std::string& path)
{
  return PlyChecker(path).Check();
}

//------------------------------------------------------------------------------
std::string CheckFile(const std::string& path)
{
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status))
  {
    return "cannot open model file '" + Printable(path) + "'";
  }
  if (!std::filesystem::is_regular_file(status))
  {
    return "model '" + Printable(path) + "' is not a regular file";
  }
  if (!std::ifstream(path).good())
  {
    return "cannot open model file '" + Printable(path) + "'";
  }
  const std::string::size_type dot = path.rfind('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(
    ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const std::string problem = ext == "stl" ? CheckSTL(path)
    : ext == "ply"                         ? CheckPLY(path)
                                           : std::string();
  return problem.empty() ? problem : "cannot read model '" + Printable(path) + "': " + problem;
}
}
