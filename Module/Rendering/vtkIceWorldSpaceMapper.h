// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceWorldSpaceMapper
 * @brief   Base of the ice mappers: fragment shaders get world-space position and normal.
 *
 * The ice optics work in world space. This vtkOpenGLPolyDataMapper adds to the surface shaders
 * `icePositionWC` and `iceNormalWC` (from the actor's matrix and VTK's vertex-buffer shift and
 * scale, whatever the lighting), the camera position and view direction, `iceViewDepth()` and
 * `iceScreenTexel()` for viewport-sized textures. It validates the input (polygons, finite points)
 * and computes point normals when there are none. Subclasses add their shading through
 * AddIceShaderParts and SetIceShaderParameters.
 */
#ifndef vtkIceWorldSpaceMapper_h
#define vtkIceWorldSpaceMapper_h

#include "RenderingIceModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkSmartPointer.h" // for members

#include <string> // for CheckInput
#include <vector> // for members

struct vtkIceShaderParts;
class vtkDataSet;
class vtkPolyData;
class vtkTextureObject;
class vtkUnsignedCharArray;

class RENDERINGICE_EXPORT vtkIceWorldSpaceMapper : public vtkOpenGLPolyDataMapper
{
public:
  vtkTypeMacro(vtkIceWorldSpaceMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Scalars are mapped from the drawn copy of the input, which keeps the input's point arrays
   * and no cell data. (Mapped from the input, scalars gave colours to a copy that may have other
   * points, which VTK then drew as cell colours: garbage.) Public, as in vtkMapper.
   */
  using Superclass::MapScalars;
  vtkUnsignedCharArray* MapScalars(vtkDataSet* input, double alpha, int& cellFlag) override;
  ///@}

  /**
   * Validates the input and adds normals before the usual OpenGL rendering.
   */
  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;

  /**
   * Bounds of the input. Also checks the input, so that bad input is reported even when the
   * renderer culls the actor (empty data has no bounds).
   */
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->Superclass::GetBounds(bounds); }

  /**
   * Why `input` cannot be drawn as ice, in one sentence (the error the mapper reports), or an
   * empty string when it can. Besides empty input and NaN or infinite coordinates it rejects
   * broken connectivity that would crash VTK's filters: a cell naming a point that does not
   * exist, a polygon or strip of fewer than three points, inconsistent cell offsets, point
   * arrays with fewer values than points, and input whose points all coincide. Applications that
   * read meshes from files can call it before handing the data to any filter.
   */
  static std::string CheckInput(vtkPolyData* input);

  /**
   * Drops the render passes VTK remembers from the last draw of each primitive (to know when to
   * rebuild shaders). A mapper drawn only inside vtkIcePass's frame (cracks, air) would otherwise
   * keep the pass, with its textures, alive after the user removed and deleted it.
   */
  void ForgetRenderPasses();

protected:
  vtkIceWorldSpaceMapper();
  ~vtkIceWorldSpaceMapper() override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;

  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  /**
   * Subclasses append their shader code for surface primitives to `parts`, which holds the
   * world-space part already; this class inserts it all (vtkIceShaderSections.h).
   */
  virtual void AddIceShaderParts(vtkIceShaderParts& parts, vtkRenderer* ren, vtkActor* act) = 0;

  /**
   * Subclasses set their uniforms; the world-space ones are already set.
   */
  virtual void SetIceShaderParameters(
    vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act) = 0;

  // The world-space camera and matrices of vtkIceWorldSpaceFS.glsl's Uniforms for `act` (and
  // iceDCWCMatrix where used): also for programs that are not this mapper's (the screen-space
  // interior's quad).
  static void SetCameraUniforms(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act);

  // Adds to the geometry shader VTK uses for edges and wide lines, if any, the copying of every
  // ice varying declared in `vs` (out TYPE iceNameVSOutput). Returns what VTK's geometry shader
  // lacks that the ice needs, empty when nothing.
  static std::string PassThroughGeometryShader(const std::string& vs, vtkShader* gs);

  // Whether the helper being compiled or drawn draws surfaces rather than lines or points.
  bool IsSurfaceHelper(const vtkOpenGLHelper* helper) const;

  // Checks the input and builds the polydata actually drawn (input plus ice normals).
  bool PrepareInput(vtkPolyData* input);

  // Called once for each new input that passed the checks, with PreparedInput built: subclasses
  // look at what they need (and warn) here.
  virtual void InputPrepared() {}

  // Whether empty input is a piece of distributed ice with nothing here (drawn as nothing,
  // silently) rather than an error.
  virtual bool EmptyInputIsPiece() { return false; }

  // The name of PreparedInput's point normals.
  static const char* GetPreparedNormalsName();
  vtkSmartPointer<vtkPolyData> PreparedInput;
  vtkMTimeType PreparedInputTime = 0;
  vtkPolyData* PreparedSource = nullptr;
  bool PreparedValid = false;
  // VTK's shaders lacked a place for the ice's code: said once.
  bool ReportedShaderPlaces = false;

  // Textures of the mapper's own activated for a draw, deactivated after it.
  std::vector<vtkTextureObject*> DrawTextures;

private:
  vtkIceWorldSpaceMapper(const vtkIceWorldSpaceMapper&) = delete;
  void operator=(const vtkIceWorldSpaceMapper&) = delete;
};

#endif
