// Private to the module: culls an ice actor's back faces for one draw where none of them can be
// seen. VTK draws both sides of a surface; on a CPU renderer every back-face fragment drawn
// before the front face hiding it runs the whole ice shader (its discard keeps the depth test
// late), which cost a quarter of a two-sided frame (Documentation/performance.md).
#ifndef vtkIceBackfaceCulling_h
#define vtkIceBackfaceCulling_h

class vtkActor;
class vtkMapper;
class vtkOpenGLState;
class vtkRenderer;

class vtkIceBackfaceCulling
{
public:
  // Whether no back face of `actor` can be seen in this draw: its input (`closedOutward`,
  // vtkIceSurfaceCheck::Closure) is closed and faces outward, it is drawn opaque as a surface
  // without clipping planes, culling of its own property or a mirroring transform, all of its
  // bounds lie beyond the active camera's near plane (the camera is outside it and no front face
  // is clipped away), and no render pass but vtkIcePass draws it (the ice's sub-passes and
  // VTK's passes set their own faces).
  static bool BackfacesHidden(
    vtkRenderer* renderer, vtkActor* actor, vtkMapper* mapper, bool closedOutward);

  // Whether a render pass other than vtkIcePass draws `actor` now (an ice sub-pass, VTK's).
  static bool InSubPass(vtkActor* actor);

  // Culls back faces until End, restoring the OpenGL state then.
  void Begin(vtkRenderer* renderer);
  void End();
  bool IsActive() const { return this->State != nullptr; }

private:
  vtkOpenGLState* State = nullptr;
  bool WasEnabled = false;
  int WasMode = 0;
};

#endif
