// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceOutputFile.h"
#include "vtkIceModelFileChecks.h"

#include "vtkImageData.h"
#include "vtkImageWriter.h"
#include "vtkJPEGWriter.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace IceOutputFile
{
namespace
{
// The temporary file being written, for the signal handler (which may only use what is
// async-signal-safe: a fixed buffer, unlink, signal, raise).
char TemporaryPath[4096];
volatile std::sig_atomic_t HaveTemporary = 0;

void OnSignal(int signal)
{
  if (HaveTemporary)
  {
    unlink(TemporaryPath);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// Names in messages are made printable: a file name may hold terminal escapes.
std::string Quote(const fs::path& path)
{
  return "'" + vtkIceModelFileChecks::Printable(path.string()) + "'";
}

std::string SystemError(int error)
{
  return std::strerror(error);
}

// `path` with its symbolic links followed (a dangling link gives the path it points to).
fs::path Resolve(const std::string& path)
{
  fs::path target = path;
  std::error_code ec;
  for (int links = 0; links < 40 && fs::is_symlink(fs::symlink_status(target, ec)); ++links)
  {
    const fs::path next = fs::read_symlink(target, ec);
    if (ec)
    {
      break;
    }
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  return target;
}

fs::path Folder(const fs::path& target)
{
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

bool WriteAll(int fd, const std::string& data, int& error)
{
  const char* next = data.data();
  std::size_t left = data.size();
  while (left > 0)
  {
    const ssize_t written = ::write(fd, next, left);
    if (written < 0 && errno == EINTR)
    {
      continue;
    }
    if (written <= 0)
    {
      error = written < 0 ? errno : ENOSPC;
      return false;
    }
    next += written;
    left -= static_cast<std::size_t>(written);
  }
  return true;
}

// Devices and pipes: no rename is possible, so the data goes straight in, checked.
std::string WriteDirectly(const fs::path& target, const std::string& data)
{
  const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0)
  {
    return "cannot write " + Quote(target) + ": " + SystemError(errno);
  }
  int error = 0;
  const bool written = WriteAll(fd, data, error);
  if (::close(fd) != 0 && written)
  {
    error = errno;
  }
  return written && error == 0 ? std::string()
                               : "cannot write " + Quote(target) + ": " + SystemError(error);
}
}

std::string CheckWritable(const std::string& path)
{
  if (path.empty())
  {
    return "no output file name";
  }
  const fs::path target = Resolve(path);
  std::error_code ec;
  const fs::file_status status = fs::status(target, ec);
  if (fs::is_directory(status))
  {
    return "cannot write " + Quote(path) + ": it is a folder";
  }
  if (fs::exists(status) && !fs::is_regular_file(status))
  {
    return ::access(target.c_str(), W_OK) == 0
      ? std::string()
      : "cannot write " + Quote(path) + ": " + SystemError(errno);
  }
  const fs::path folder = Folder(target);
  if (!fs::is_directory(fs::status(folder, ec)))
  {
    return "cannot write " + Quote(path) + ": no folder " + Quote(folder);
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
  {
    return "cannot write " + Quote(path) + ": folder " + Quote(folder) + ": " + SystemError(errno);
  }
  return std::string();
}

std::string Write(const std::string& path, const std::string& data)
{
  const std::string problem = CheckWritable(path);
  if (!problem.empty())
  {
    return problem;
  }
  const fs::path target = Resolve(path);
  std::error_code ec;
  const fs::file_status status = fs::status(target, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
  {
    return WriteDirectly(target, data);
  }

  const std::string pattern =
    (Folder(target) / ("." + target.filename().string() + ".XXXXXX")).string();
  if (pattern.size() >= sizeof(TemporaryPath))
  {
    return "cannot write " + Quote(path) + ": the path is too long";
  }
  std::copy(pattern.begin(), pattern.end(), TemporaryPath);
  TemporaryPath[pattern.size()] = '\0';
  // Blocked while the name is set up, so that a signal never sees half of it.
  sigset_t signals;
  sigset_t previous;
  sigfillset(&signals);
  sigprocmask(SIG_BLOCK, &signals, &previous);
  const int fd = ::mkstemp(TemporaryPath);
  HaveTemporary = fd >= 0;
  const int createError = errno;
  sigprocmask(SIG_SETMASK, &previous, nullptr);
  if (fd < 0)
  {
    return "cannot write " + Quote(path) + ": cannot create a file in " + Quote(Folder(target)) +
      ": " + SystemError(createError);
  }

  // The new file gets the old one's permissions, or those a new file would get (mkstemp's are
  // 0600).
  mode_t mode = 0;
  struct stat old;
  if (::stat(target.c_str(), &old) == 0)
  {
    mode = old.st_mode & 07777;
  }
  else
  {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  int error = 0;
  bool ok = ::fchmod(fd, mode) == 0 || (error = errno, false);
  ok = ok && WriteAll(fd, data, error);
  ok = ok && (::fsync(fd) == 0 || (error = errno, false));
  const bool closed = ::close(fd) == 0;
  if (ok && !closed)
  {
    ok = false;
    error = errno;
  }
  ok = ok && (::rename(TemporaryPath, target.c_str()) == 0 || (error = errno, false));
  if (!ok)
  {
    ::unlink(TemporaryPath);
  }
  HaveTemporary = 0;
  return ok ? std::string() : "cannot write " + Quote(path) + ": " + SystemError(error);
}

std::string ImageFormat(const std::string& path)
{
  std::string name = fs::path(path).filename().string();
  std::transform(
    name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  auto endsWith = [&name](const std::string& end) {
    return name.size() > end.size() && name.compare(name.size() - end.size(), end.size(), end) == 0;
  };
  if (endsWith(".png"))
  {
    return "png";
  }
  if (endsWith(".jpg") || endsWith(".jpeg"))
  {
    return "jpeg";
  }
  return std::string();
}

std::string WriteImage(const std::string& path, vtkImageData* image)
{
  const std::string format = ImageFormat(path);
  vtkSmartPointer<vtkImageWriter> writer;
  if (format == "png")
  {
    auto png = vtkSmartPointer<vtkPNGWriter>::New();
    png->WriteToMemoryOn();
    writer = png;
  }
  else if (format == "jpeg")
  {
    auto jpeg = vtkSmartPointer<vtkJPEGWriter>::New();
    jpeg->WriteToMemoryOn();
    jpeg->SetQuality(95);
    writer = jpeg;
  }
  else
  {
    return "cannot write " + Quote(path) + ": its name must end in .png, .jpg or .jpeg";
  }
  writer->SetInputData(image);
  writer->Write();
  vtkUnsignedCharArray* bytes = format == "png" ? vtkPNGWriter::SafeDownCast(writer)->GetResult()
                                                : vtkJPEGWriter::SafeDownCast(writer)->GetResult();
  if (writer->GetErrorCode() != 0 || !bytes || bytes->GetNumberOfValues() == 0)
  {
    return "cannot encode the image for " + Quote(path);
  }
  return Write(path,
    std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)),
      static_cast<std::size_t>(bytes->GetNumberOfValues())));
}

void RemoveTemporaryOnSignals()
{
  for (const int signal : { SIGINT, SIGTERM, SIGHUP, SIGQUIT })
  {
    std::signal(signal, OnSignal);
  }
}
}
