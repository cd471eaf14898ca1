// What vtkIcePass and its sub-passes ask of the ice mappers in a frame: which props are ice, what
// each needs rendered, and its cracks and air drawn. These are not vtkIceMapper's public API
// (neither wrapped nor installed): the mapper grants them to this class only. Inside the module.
#ifndef vtkIceMapperAccess_h
#define vtkIceMapperAccess_h

#include "vtkActor.h"
#include "vtkIceMapper.h"

class vtkIceMapperAccess
{
public:
  // The vtkIceMapper of `prop` if it is a visible vtkActor drawn by one, else null.
  static vtkIceMapper* Of(vtkProp* prop)
  {
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    return actor && actor->GetVisibility() ? vtkIceMapper::SafeDownCast(actor->GetMapper())
                                           : nullptr;
  }

  // What the ice needs the pass to render for it this frame: vtkIceFrame::Need bits.
  static int FrameNeeds(vtkIceMapper* mapper) { return mapper->GetFrameNeeds(); }

  // What the frame gives the surface program of `prop` now (vtkIceFrame::Input bits).
  static int FrameInputs(vtkIceMapper* mapper, vtkProp* prop)
  {
    return mapper->GetFrameInputs(prop);
  }

  // Draws the cracks of `actor`. `overlay`: over the rendered scene, with additive blending;
  // otherwise with the current state (into the back-face normal texture).
  static void DrawCracks(vtkIceMapper* mapper, vtkRenderer* ren, vtkActor* actor, bool overlay)
  {
    mapper->RenderCracks(ren, actor, overlay);
  }

  // Draws the air planes of `actor` over the rendered scene, back to front for the camera.
  static void DrawAir(vtkIceMapper* mapper, vtkRenderer* ren, vtkActor* actor)
  {
    mapper->RenderAir(ren, actor);
  }
};

#endif
