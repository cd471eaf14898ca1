// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Resource measurements for the long-running and lifecycle tests: OpenGL errors, a census of the
// OpenGL object names alive in the current context, and the process's memory.
#ifndef IceTestResources_h
#define IceTestResources_h

#include <string>

class vtkRenderWindow;

namespace IceTest
{
// Makes the window's context current and drains glGetError (as vtkOpenGLError.h does, but also
// in Release builds). Returns "" when there was no error, else the errors in words.
std::string TakeGLErrors(vtkRenderWindow* window);

// How many names of each kind of OpenGL object exist in the window's context, found by probing
// every name with glIs* (textures, buffers, framebuffers, renderbuffers, vertex arrays, shader
// programs, shaders, queries). Names are small integers handed out by the driver; the probe covers
// 1 to past the largest name in use (and past the largest ever seen by this census), so a leak of
// any object of these kinds shows as a larger count.
struct GLCensus
{
  int Textures = 0;
  int Buffers = 0;
  int Framebuffers = 0;
  int Renderbuffers = 0;
  int VertexArrays = 0;
  int Programs = 0;
  int Shaders = 0;
  int Queries = 0;
  int Total() const
  {
    return this->Textures + this->Buffers + this->Framebuffers + this->Renderbuffers +
      this->VertexArrays + this->Programs + this->Shaders + this->Queries;
  }
  std::string Describe() const;
};
GLCensus TakeGLCensus(vtkRenderWindow* window);

// Counts every VTK error and warning of the process (vtkOutputWindow). Install() makes it VTK's
// output window until Uninstall(); with `quiet` the messages are not printed (nor logged by
// vtkLogger), for tests that expect them.
class MessageCounter
{
public:
  void Install(bool quiet = false);
  void Uninstall();
  int Errors() const;
  int Warnings() const;
  std::string Last() const;
};

// Resident set size (VmRSS of /proc/self/status) in KiB, 0 if unknown.
long ResidentKiB();

// Bytes of heap in use (glibc mallinfo2: arena and mmapped blocks in use), 0 if unknown (for
// instance under AddressSanitizer, which replaces malloc).
long HeapInUseKiB();
}

#endif
