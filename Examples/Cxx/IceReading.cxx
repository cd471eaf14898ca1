// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "IceReading.h"
#include "vtkIceModelFileChecks.h"

#include "vtkAlgorithm.h"
#include "vtkIceMapper.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace IceReading
{
namespace
{
// Collects VTK's error text while loading files, so that ice-render reports one clean line.
class CapturedOutput : public vtkOutputWindow
{
public:
  static CapturedOutput* New() { VTK_STANDARD_NEW_BODY(CapturedOutput); }
  void DisplayText(const char* text) override
  {
    if (this->FirstMessage.empty() && text)
    {
      // Keep the message, not VTK's preamble: "ERROR: In file, line N\nvtkClass (address): " or,
      // for generic messages, "Generic Warning: In file, line N\n".
      std::string message = text;
      const std::string::size_type start = message.find("): ");
      const std::string::size_type newline = message.find('\n');
      if (start != std::string::npos)
      {
        message = message.substr(start + 3);
      }
      else if (newline != std::string::npos && newline + 1 < message.size())
      {
        message = message.substr(newline + 1);
      }
      std::replace(message.begin(), message.end(), '\n', ' ');
      message.erase(message.find_last_not_of(' ') + 1);
      this->FirstMessage = message;
    }
  }
  std::string FirstMessage;
};

// Sends what is written to stderr to a temporary file until Release(), which gives it back.
class HeldStderr
{
public:
  HeldStderr()
  {
    std::fflush(stderr);
    this->File = std::tmpfile();
    this->Saved = this->File ? ::dup(STDERR_FILENO) : -1;
    if (this->Saved >= 0)
    {
      ::dup2(::fileno(this->File), STDERR_FILENO);
    }
  }
  ~HeldStderr() { this->Release(); }
  std::string Release()
  {
    std::string text;
    if (this->Saved < 0)
    {
      return text;
    }
    std::fflush(stderr);
    ::dup2(this->Saved, STDERR_FILENO);
    ::close(this->Saved);
    this->Saved = -1;
    std::rewind(this->File);
    char buffer[4096];
    size_t n;
    while ((n = std::fread(buffer, 1, sizeof(buffer), this->File)) > 0 && text.size() < 65536)
    {
      text.append(buffer, n);
    }
    std::fclose(this->File);
    this->File = nullptr;
    return text;
  }

private:
  std::FILE* File = nullptr;
  int Saved = -1;
};

bool WriteAll(int fd, const std::string& data)
{
  for (std::size_t done = 0; done < data.size();)
  {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string ReadAll(int fd)
{
  std::string data;
  char buffer[65536];
  for (;;)
  {
    const ssize_t n = ::read(fd, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      return data;
    }
    data.append(buffer, static_cast<std::size_t>(n));
  }
}

// Removes the point arrays with fewer values than `output` has points; says which, or nothing.
std::string DropShortPointArrays(vtkPolyData* output)
{
  std::string dropped;
  vtkPointData* pointData = output->GetPointData();
  const vtkIdType points = output->GetNumberOfPoints();
  for (int a = pointData->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    vtkAbstractArray* array = pointData->GetAbstractArray(a);
    if (array && array->GetNumberOfTuples() < points)
    {
      dropped += std::string(dropped.empty() ? "" : "; ") + "point array '" +
        vtkIceModelFileChecks::Printable(array->GetName() ? array->GetName() : "(unnamed)") +
        "' (" + std::to_string(array->GetNumberOfTuples()) + " values for " +
        std::to_string(points) + " points)";
      pointData->RemoveArray(a);
    }
  }
  return dropped.empty() ? dropped : "dropped its " + dropped + ", which the ice does not use";
}

// The child's answer: 'W', a warning and a newline when there is one, then 'D' and the output as
// a binary VTK XML file, or 'E' and the message.
[[noreturn]] void Answer(int fd, vtkAlgorithm* reader)
{
  std::string message;
  std::string answer;
  std::string warning;
  vtkPolyData* output = nullptr;
  if (UpdateQuietly(reader, message))
  {
    output = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
    if (output)
    {
      warning = DropShortPointArrays(output);
    }
    // Broken connectivity crashes VTK's writer too: the checks go first.
    message = output ? vtkIceMapper::CheckInput(output) : "the reader gave no polydata";
  }
  if (message.empty())
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(output);
    writer->SetDataModeToBinary();
    writer->SetCompressorTypeToNone();
    writer->WriteToOutputStringOn();
    answer = writer->Write()
      ? (warning.empty() ? "" : "W" + warning + "\n") + "D" + writer->GetOutputString()
      : std::string("Ecannot pass the model on (out of memory?)");
  }
  else
  {
    answer = "E" + message;
  }
  // _exit: no destructors or atexit handlers of the parent's objects run twice.
  ::_exit(WriteAll(fd, answer) ? 0 : 1);
}
}

bool UpdateQuietly(vtkAlgorithm* algorithm, std::string& error)
{
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkNew<CapturedOutput> capture;
  vtkOutputWindow::SetInstance(capture);
  // VTK also logs errors to stderr through vtkLogger, bypassing the output window.
  const vtkLogger::Verbosity verbosity = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  HeldStderr held;
  try
  {
    algorithm->Update();
  }
  catch (const std::bad_alloc&)
  {
    // A header announcing more data than memory holds (readers allocate before they read).
    capture->FirstMessage = "not enough memory for what the file announces";
  }
  const std::string printed = held.Release();
  vtkLogger::SetStderrVerbosity(verbosity);
  vtkOutputWindow::SetInstance(previous);
  error = vtkIceModelFileChecks::Printable(capture->FirstMessage);
  if (error.empty() && !printed.empty())
  {
    std::fputs(vtkIceModelFileChecks::Printable(printed, 4096).c_str(), stderr);
    std::fputs("\n", stderr);
  }
  return error.empty();
}

vtkSmartPointer<vtkPolyData> ReadPolyDataIsolated(
  vtkAlgorithm* reader, std::string& error, std::string* warning)
{
  int fds[2];
  if (::pipe(fds) != 0)
  {
    error = std::string("cannot start the reader: ") + std::strerror(errno);
    return nullptr;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = ::fork();
  if (child < 0)
  {
    error = std::string("cannot start the reader: ") + std::strerror(errno);
    ::close(fds[0]);
    ::close(fds[1]);
    return nullptr;
  }
  if (child == 0)
  {
    ::close(fds[0]);
    // Whatever a crashing reader or a sanitizer prints would not be one clean line.
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDERR_FILENO);
    Answer(fds[1], reader);
  }
  ::close(fds[1]);
  std::string answer = ReadAll(fds[0]);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
  {
  }
  if (WIFSIGNALED(status) || !WIFEXITED(status) || WEXITSTATUS(status) != 0 || answer.empty())
  {
    error = WIFSIGNALED(status) ? "the reader crashed on it (" +
        std::string(::strsignal(WTERMSIG(status))) + "): the file is broken"
                                : "the reader failed on it: the file is broken";
    return nullptr;
  }
  if (answer[0] == 'E')
  {
    error = answer.substr(1);
    return nullptr;
  }
  if (answer[0] == 'W')
  {
    const std::string::size_type end = answer.find('\n');
    if (warning)
    {
      *warning = answer.substr(1, end - 1);
    }
    answer.erase(0, end == std::string::npos ? answer.size() : end + 1);
  }
  vtkNew<vtkXMLPolyDataReader> copy;
  copy->ReadFromInputStringOn();
  copy->SetInputString(answer.substr(1));
  if (!UpdateQuietly(copy, error))
  {
    error = "cannot pass the model on from the reader: " + error;
    return nullptr;
  }
  return copy->GetOutput();
}
}
