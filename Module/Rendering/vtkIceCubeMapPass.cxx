// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIceCubeMapPass.h"

#include "vtkIceCubeMapTexture.h"

#include "vtkIceCubeMapCompositor.h"
#include "vtkIceMapperAccess.h"

#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"
#include "vtkIceVTKCompat.h"

#include <algorithm>
#include <functional>
#include <map>
#include <vector>

vtkStandardNewMacro(vtkIceCubeMapPass);
vtkCxxSetObjectMacro(vtkIceCubeMapPass, DelegatePass, vtkRenderPass);
vtkCxxSetObjectMacro(vtkIceCubeMapPass, Compositor, vtkIceCubeMapCompositor);

namespace
{
// Whether the renderer's environment is HDR: the cube maps then keep values above 1. The texture
// would bring its input up to date when it is first drawn; this pass runs first.
bool HighDynamicRange(vtkRenderer* renderer)
{
  return vtkIceCubeMapTexture::HoldsHighDynamicRange(renderer->GetEnvironmentTexture());
}
}

namespace
{
// A camera per OpenGL cube face, so that the rendered image's right and up axes are the face's
// s and t axes (direction x up = right).
struct FaceView
{
  double Direction[3];
  double Up[3];
};
const FaceView Faces[6] = {
  { { 1, 0, 0 }, { 0, -1, 0 } },
  { { -1, 0, 0 }, { 0, -1, 0 } },
  { { 0, 1, 0 }, { 0, 0, 1 } },
  { { 0, -1, 0 }, { 0, 0, -1 } },
  { { 0, 0, 1 }, { 0, -1, 0 } },
  { { 0, 0, -1 }, { 0, -1, 0 } },
};

// Whether a box may be seen in the 90° frustum of `face` from `center`: the frustum is where the
// face's axis coordinate dominates, |p_j| <= s p_k for the other axes j.
bool IntersectsFace(const double bounds[6], const double center[3], int face)
{
  const int k = face / 2;
  const double s = face % 2 ? -1.0 : 1.0;
  for (int j = 0; j < 3; ++j)
  {
    if (j == k)
    {
      continue;
    }
    for (double q : { 1.0, -1.0 })
    {
      // Largest value of s p_k - q p_j over the box; negative means the box is outside.
      const double pk = s > 0 ? bounds[2 * k + 1] - center[k] : center[k] - bounds[2 * k];
      const double pj = q > 0 ? center[j] - bounds[2 * j] : bounds[2 * j + 1] - center[j];
      if (pk + pj < 0.0)
      {
        return false;
      }
    }
  }
  return true;
}

void HashCombine(size_t& seed, size_t value)
{
  seed ^= value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
}

// The props a cube map shows: visible 3D props that are not ice.
std::vector<vtkProp*> SceneProps(vtkRenderer* renderer)
{
  std::vector<vtkProp*> scene;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility() && vtkProp3D::SafeDownCast(prop) && !vtkIceMapperAccess::Of(prop))
    {
      scene.push_back(prop);
    }
  }
  return scene;
}

// A background as vtkViewport has it.
struct Background
{
  double Color[3];
  double Color2[3];
  bool Gradient;
};

// The renderer's background, or the compositor's when it gives one (IceT paints the renderer's
// black while the ranks draw).
Background GetBackground(vtkRenderer* renderer, vtkIceCubeMapCompositor* compositor)
{
  Background background;
  const bool own = !compositor || !compositor->GetUseBackground();
  std::copy_n(own ? renderer->GetBackground() : compositor->GetBackground(), 3, background.Color);
  std::copy_n(
    own ? renderer->GetBackground2() : compositor->GetBackground2(), 3, background.Color2);
  background.Gradient =
    own ? renderer->GetGradientBackground() : compositor->GetGradientBackground();
  return background;
}

void SetBackground(vtkRenderer* renderer, const Background& background)
{
  renderer->SetBackground(background.Color[0], background.Color[1], background.Color[2]);
  renderer->SetBackground2(background.Color2[0], background.Color2[1], background.Color2[2]);
  renderer->SetGradientBackground(background.Gradient);
}

// Changes whenever what the cube map at `center` shows may have changed; camera-following lights
// and the camera itself are left out on purpose.
size_t SceneSignature(vtkRenderer* renderer, const Background& background,
  const std::vector<vtkProp*>& scene, const double center[3], int faceSize)
{
  size_t seed = std::hash<int>()(faceSize);
  for (int i = 0; i < 3; ++i)
  {
    HashCombine(seed, std::hash<double>()(center[i]));
    HashCombine(seed, std::hash<double>()(background.Color[i]));
    HashCombine(seed, std::hash<double>()(background.Color2[i]));
  }
  HashCombine(seed, std::hash<bool>()(background.Gradient));
  for (vtkProp* prop : scene)
  {
    HashCombine(seed, std::hash<const void*>()(prop));
    HashCombine(seed, std::hash<vtkMTimeType>()(prop->GetRedrawMTime()));
  }
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (light->LightTypeIsSceneLight())
    {
      HashCombine(seed, std::hash<const void*>()(light));
      HashCombine(seed, std::hash<vtkMTimeType>()(light->GetMTime()));
    }
  }
  return seed;
}
}

class vtkIceCubeMapPass::vtkInternals
{
public:
  struct CubeMap
  {
    vtkSmartPointer<vtkTextureObject> Texture;
    size_t Signature = 0;
    int NextFace = 0;
    int PendingFaces = 0;
    bool Rendered = false;
  };
  std::map<vtkProp*, CubeMap> Maps;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  vtkNew<vtkCamera> FaceCamera;
  vtkNew<vtkTransform> LightTransform;
  bool UpdateRequested = false;
  std::vector<float> FaceColors; // a face read back for compositing, kept between faces
  std::vector<float> FaceDepths;

  // Renders the next pending face of `map` from `center`, into half floats when
  // `highDynamicRange`.
  void RenderFace(vtkIceCubeMapPass* pass, vtkOpenGLRenderer* renderer, CubeMap& map,
    const std::vector<vtkProp*>& scene, const double center[3], bool highDynamicRange);

private:
  void Allocate(
    vtkIceCubeMapPass* pass, vtkOpenGLRenderWindow* window, CubeMap& map, bool highDynamicRange);
  void SetupCamera(vtkIceCubeMapPass* pass, int face, const double center[3],
    const std::vector<vtkProp*>& scene, vtkCamera* mainCamera);
  // Replaces the face just rendered into the bound frame buffer by its composite over processes.
  void CompositeFace(vtkIceCubeMapPass* pass, CubeMap& map, int face);
};

//------------------------------------------------------------------------------
void vtkIceCubeMapPass::vtkInternals::Allocate(
  vtkIceCubeMapPass* pass, vtkOpenGLRenderWindow* window, CubeMap& map, bool highDynamicRange)
{
  const unsigned int size = static_cast<unsigned int>(pass->FaceSize);
  const int type = highDynamicRange ? VTK_FLOAT : VTK_UNSIGNED_CHAR;
  if (map.Texture &&
    (map.Texture->GetWidth() != size || map.Texture->GetContext() != window ||
      map.Texture->GetVTKDataType() != type))
  {
    map.Texture->ReleaseGraphicsResources(window);
    map.Texture = nullptr;
  }
  if (!map.Texture)
  {
    map.Texture = vtkSmartPointer<vtkTextureObject>::New();
    map.Texture->SetContext(window);
    map.Texture->SetMinificationFilter(vtkTextureObject::Linear);
    map.Texture->SetMagnificationFilter(vtkTextureObject::Linear);
    map.Texture->SetWrapS(vtkTextureObject::ClampToEdge);
    map.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    map.Texture->SetWrapR(vtkTextureObject::ClampToEdge);
    // Half floats for an HDR environment: its light reaches the ice as the static environment
    // texture gives it, instead of clamped to 1 by an 8-bit target. 8 bits otherwise: llvmpipe
    // samples them faster (a float cube map cost about 15 ms a frame in ice-bench's scenes).
    map.Texture->SetInternalFormat(highDynamicRange ? GL_RGBA16F : GL_RGBA8);
    map.Texture->SetFormat(GL_RGBA);
    map.Texture->SetDataType(highDynamicRange ? GL_FLOAT : GL_UNSIGNED_BYTE);
    void* noData[6] = { nullptr, nullptr, nullptr, nullptr, nullptr, nullptr };
    map.Texture->CreateCubeFromRaw(size, size, 4, type, noData);
    map.Rendered = false;
  }
  if (!this->FrameBuffer || this->FrameBuffer->GetContext() != window)
  {
    this->FrameBuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->FrameBuffer->SetContext(window);
  }
}

//------------------------------------------------------------------------------
void vtkIceCubeMapPass::vtkInternals::SetupCamera(vtkIceCubeMapPass* pass, int face,
  const double center[3], const std::vector<vtkProp*>& scene, vtkCamera* mainCamera)
{
  // Near and far from the distance to the scene's farthest corner.
  double farthest = 1.0;
  for (vtkProp* prop : scene)
  {
    const double* b = prop->GetBounds();
    if (!b || !vtkMath::AreBoundsInitialized(b))
    {
      continue;
    }
    for (int corner = 0; corner < 8; ++corner)
    {
      const double p[3] = { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)] };
      farthest = std::max(farthest, std::sqrt(vtkMath::Distance2BetweenPoints(p, center)));
    }
  }
  if (pass->Compositor)
  {
    // One depth range on every process: the faces' depths are compared when composited.
    pass->Compositor->MaximumOverProcesses(&farthest, 1);
  }
  vtkCamera* camera = this->FaceCamera;
  const FaceView& view = Faces[face];
  camera->SetPosition(center[0], center[1], center[2]);
  camera->SetFocalPoint(
    center[0] + view.Direction[0], center[1] + view.Direction[1], center[2] + view.Direction[2]);
  camera->SetViewUp(view.Up[0], view.Up[1], view.Up[2]);
  camera->SetViewAngle(90.0);
  camera->SetUseExplicitAspectRatio(true);
  camera->SetExplicitAspectRatio(1.0);
  camera->SetClippingRange(1e-4 * farthest, 1.01 * farthest);

  // Camera-following lights keep the direction they have for the main camera: their view-space
  // direction is mapped by R_face * R_main^T.
  vtkMatrix4x4* faceView = camera->GetViewTransformMatrix();
  vtkMatrix4x4* mainView = mainCamera->GetViewTransformMatrix();
  vtkNew<vtkMatrix4x4> rotation;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double sum = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        sum += faceView->GetElement(i, k) * mainView->GetElement(j, k);
      }
      rotation->SetElement(i, j, sum);
    }
  }
  this->LightTransform->SetMatrix(rotation);
}

//------------------------------------------------------------------------------
void vtkIceCubeMapPass::vtkInternals::RenderFace(vtkIceCubeMapPass* pass,
  vtkOpenGLRenderer* renderer, CubeMap& map, const std::vector<vtkProp*>& scene,
  const double center[3], bool highDynamicRange)
{
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  this->Allocate(pass, window, map, highDynamicRange);
  const int face = map.NextFace;
  map.NextFace = (map.NextFace + 1) % 6;
  --map.PendingFaces;

  std::vector<vtkProp*> visible;
  for (vtkProp* prop : scene)
  {
    const double* b = prop->GetBounds();
    if (!pass->FrustumCulling || !b || !vtkMath::AreBoundsInitialized(b) ||
      IntersectsFace(b, center, face))
    {
      visible.push_back(prop);
    }
  }
  pass->NumberOfCulledProps += static_cast<vtkIdType>(scene.size() - visible.size());

  vtkSmartPointer<vtkCamera> mainCamera = renderer->GetActiveCamera();
  this->SetupCamera(pass, face, center, scene, mainCamera);
  renderer->SetActiveCamera(this->FaceCamera);
  renderer->SetUserLightTransform(this->LightTransform);
  const Background frameBackground = GetBackground(renderer, nullptr);
  SetBackground(renderer, GetBackground(renderer, pass->Compositor));

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglScissor scissorSaver(state);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  state->PushFramebufferBindings();
  this->FrameBuffer->Bind();
  this->FrameBuffer->AddColorAttachment(0, map.Texture, 0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + face);
  this->FrameBuffer->AddDepthAttachment();
  this->FrameBuffer->ActivateBuffer(0);
  // Not Start(): it switches blending off, and translucent props are blended in the faces as in
  // the frame (which went on without blending after the faces). The camera pass sets the
  // viewport and scissor box from the framebuffer's size.
  this->FrameBuffer->StartNonOrtho(pass->FaceSize, pass->FaceSize);

  vtkRenderState faceState(renderer);
  faceState.SetPropArrayAndCount(visible.data(), static_cast<int>(visible.size()));
  faceState.SetFrameBuffer(this->FrameBuffer);
  pass->DelegatePass->Render(&faceState);
  pass->NumberOfRenderedProps += pass->DelegatePass->GetNumberOfRenderedProps();
  if (pass->Compositor)
  {
    this->CompositeFace(pass, map, face);
  }

  this->FrameBuffer->RemoveColorAttachment(0);
  state->PopFramebufferBindings();
  SetBackground(renderer, frameBackground);
  renderer->SetUserLightTransform(nullptr);
  renderer->SetActiveCamera(mainCamera);
  ++pass->NumberOfFaceRenders;
  map.Rendered = map.Rendered || map.PendingFaces == 0;
}

//------------------------------------------------------------------------------
void vtkIceCubeMapPass::vtkInternals::CompositeFace(vtkIceCubeMapPass* pass, CubeMap& map, int face)
{
  const int size = pass->FaceSize;
  const vtkIdType pixels = static_cast<vtkIdType>(size) * size;
  std::vector<float>& rgba = this->FaceColors;
  std::vector<float>& depth = this->FaceDepths;
  rgba.resize(4 * pixels);
  depth.resize(pixels);
  // A compositing pass may leave pixel buffers bound (IceT): read into and draw from memory.
  GLint packBuffer = 0;
  GLint unpackBuffer = 0;
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
  glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  this->FrameBuffer->ActivateReadBuffer(0);
  glReadPixels(0, 0, size, size, GL_RGBA, GL_FLOAT, rgba.data());
  glReadPixels(0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  pass->Compositor->CompositeFace(pixels, rgba.data(), depth.data());
  map.Texture->Activate();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(
    GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, 0, 0, size, size, GL_RGBA, GL_FLOAT, rgba.data());
  map.Texture->Deactivate();
  glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(packBuffer));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpackBuffer));
}

//------------------------------------------------------------------------------
vtkIceCubeMapPass::vtkIceCubeMapPass()
  : Internals(new vtkInternals)
{
  vtkRenderStepsPass* steps = vtkRenderStepsPass::New();
  this->SetDelegatePass(steps);
  steps->Delete();
}

//------------------------------------------------------------------------------
vtkIceCubeMapPass::~vtkIceCubeMapPass()
{
  this->SetDelegatePass(nullptr);
  this->SetCompositor(nullptr);
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkIceCubeMapPass::Update()
{
  this->Internals->UpdateRequested = true;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIceCubeMapPass::GetCubeMap(vtkProp* iceProp)
{
  auto found = this->Internals->Maps.find(iceProp);
  if (found == this->Internals->Maps.end() && iceProp && iceProp->GetPropertyKeys())
  {
    // A prop that draws through an inner actor sharing its property keys (ParaView's
    // vtkPVLODActor): the mapper is handed the inner actor.
    found = std::find_if(
      this->Internals->Maps.begin(), this->Internals->Maps.end(), [iceProp](const auto& entry) {
        return entry.first->GetPropertyKeys() == iceProp->GetPropertyKeys();
      });
  }
  return found != this->Internals->Maps.end() && found->second.Rendered
    ? found->second.Texture.Get()
    : nullptr;
}

//------------------------------------------------------------------------------
void vtkIceCubeMapPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass: cube maps are not rendered.");
    return;
  }
  vtkOpenGLRenderer* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());

  // Forget cube maps of props that are no longer ice in this renderer.
  std::vector<vtkProp*> iceProps(s->GetPropArray(), s->GetPropArray() + s->GetPropArrayCount());
  for (auto it = this->Internals->Maps.begin(); it != this->Internals->Maps.end();)
  {
    const bool current = std::find(iceProps.begin(), iceProps.end(), it->first) != iceProps.end();
    if (!current && it->second.Texture)
    {
      it->second.Texture->ReleaseGraphicsResources(window);
    }
    it = current ? std::next(it) : this->Internals->Maps.erase(it);
  }

  const std::vector<vtkProp*> scene = SceneProps(renderer);
  // Once a frame: the texel type follows the environment texture's.
  const bool highDynamicRange = HighDynamicRange(renderer);
  const int texelType = highDynamicRange ? VTK_FLOAT : VTK_UNSIGNED_CHAR;
  const bool updateRequested = this->Internals->UpdateRequested;
  this->Internals->UpdateRequested = false;
  struct Update
  {
    vtkInternals::CubeMap* Map;
    double Center[3];
    double Restart; // 0 or 1: a double, to agree with other processes on it
  };
  std::vector<Update> updates;
  const Background faceBackground = GetBackground(renderer, this->Compositor);
  for (vtkProp* iceProp : iceProps)
  {
    Update update;
    const double* bounds = iceProp->GetBounds();
    if (!bounds || !vtkMath::AreBoundsInitialized(bounds))
    {
      continue;
    }
    for (int i = 0; i < 3; ++i)
    {
      update.Center[i] = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]);
    }
    const size_t signature =
      SceneSignature(renderer, faceBackground, scene, update.Center, this->FaceSize);
    auto inserted = this->Internals->Maps.emplace(iceProp, vtkInternals::CubeMap());
    update.Map = &inserted.first->second;
    // A new size or texel type reallocates the texture: all six faces are rendered again.
    const vtkSmartPointer<vtkTextureObject>& texture = update.Map->Texture;
    const bool reallocated = texture &&
      (texture->GetWidth() != static_cast<unsigned int>(this->FaceSize) ||
        texture->GetVTKDataType() != texelType);
    const bool restart = inserted.second || reallocated || updateRequested ||
      (this->UpdateMode == EveryFrame && update.Map->PendingFaces == 0) ||
      (this->UpdateMode == OnChange && signature != update.Map->Signature);
    update.Map->Signature = signature;
    update.Restart = restart ? 1.0 : 0.0;
    updates.push_back(update);
  }
  if (this->Compositor)
  {
    // What one process's part of the scene changes is in every process's cube maps: all update
    // together (each face is a collective operation).
    std::vector<double> restarts;
    for (const Update& update : updates)
    {
      restarts.push_back(update.Restart);
    }
    this->Compositor->MaximumOverProcesses(restarts.data(), static_cast<int>(restarts.size()));
    for (size_t i = 0; i < updates.size(); ++i)
    {
      updates[i].Restart = restarts[i];
    }
  }
  for (Update& update : updates)
  {
    if (update.Restart > 0.0)
    {
      update.Map->PendingFaces = 6;
    }
    const int faces = std::min(update.Map->PendingFaces, this->FacesPerFrame);
    for (int f = 0; f < faces; ++f)
    {
      this->Internals->RenderFace(
        this, renderer, *update.Map, scene, update.Center, highDynamicRange);
    }
    if (faces > 0)
    {
      // A prop's first render makes what it lacked (an actor's vtkProperty, its textures): that
      // changes its redraw time but not the picture, so the scene is signed as just drawn.
      update.Map->Signature =
        SceneSignature(renderer, faceBackground, scene, update.Center, this->FaceSize);
    }
  }
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
void vtkIceCubeMapPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  for (auto& entry : this->Internals->Maps)
  {
    if (entry.second.Texture)
    {
      entry.second.Texture->ReleaseGraphicsResources(w);
    }
  }
  this->Internals->Maps.clear();
  if (this->Internals->FrameBuffer)
  {
    this->Internals->FrameBuffer->ReleaseGraphicsResources(w);
    this->Internals->FrameBuffer = nullptr;
  }
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
}

//------------------------------------------------------------------------------
void vtkIceCubeMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* modes[3] = { "EveryFrame", "OnChange", "Manual" };
  os << indent << "UpdateMode: " << modes[this->UpdateMode] << "\n";
  os << indent << "FaceSize: " << this->FaceSize << "\n";
  os << indent << "FacesPerFrame: " << this->FacesPerFrame << "\n";
  os << indent << "FrustumCulling: " << (this->FrustumCulling ? "On" : "Off") << "\n";
  os << indent << "NumberOfFaceRenders: " << this->NumberOfFaceRenders << "\n";
  os << indent << "NumberOfCulledProps: " << this->NumberOfCulledProps << "\n";
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "Compositor: " << this->Compositor << "\n";
}
