// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// The ice surface's triangle tree (vtkIceTriangleBVH) as the two texture buffers the trace of
// vtkIceTraceFS.glsl reads, for vtkIceMapper::MaxBounces: rebuilt on the CPU when the mapper's
// prepared input changes, uploaded when that happens or the context is new.
#ifndef vtkIceTraceTextures_h
#define vtkIceTraceTextures_h

#include "vtkMatrix4x4.h" // for the member
#include "vtkNew.h"       // for the member
#include "vtkSmartPointer.h"
#include "vtkType.h" // for vtkMTimeType

class vtkActor;
class vtkIceTriangleBVH;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkIceTraceTextures
{
public:
  vtkIceTraceTextures();
  ~vtkIceTraceTextures();

  // The tree of `surface`'s triangles with the point normals named `normals`, built when the
  // surface changed since the last call. False when it has none (nothing to trace: no triangle,
  // or more than vtkIceTriangleBVH::MaximumTriangles).
  bool Update(vtkPolyData* surface, const char* normals);
  // Uploads what changed, activates both textures and sets the trace's uniforms for a draw of
  // `actor` with up to `maxBounces` hits; `active` receives the two textures to deactivate after
  // the draw.
  void Activate(vtkOpenGLRenderWindow* window, vtkShaderProgram* program, vtkActor* actor,
    int maxBounces, vtkTextureObject* active[2]);
  void ReleaseGraphicsResources(vtkWindow* window);

  vtkIceTriangleBVH* GetTree() const { return this->Tree; }

private:
  vtkSmartPointer<vtkIceTriangleBVH> Tree;
  vtkPolyData* Surface = nullptr;
  vtkMTimeType SurfaceTime = 0;
  bool Usable = false;
  vtkMTimeType UploadedTime = 0; // the tree's MTime when uploaded
  vtkSmartPointer<vtkOpenGLBufferObject> NodeBuffer;
  vtkSmartPointer<vtkOpenGLBufferObject> TriangleBuffer;
  vtkSmartPointer<vtkTextureObject> Nodes;
  vtkSmartPointer<vtkTextureObject> Triangles;
  vtkNew<vtkMatrix4x4> WorldToModel; // set every draw: kept, not allocated each time

  vtkIceTraceTextures(const vtkIceTraceTextures&) = delete;
  void operator=(const vtkIceTraceTextures&) = delete;
};

#endif
