// ice-render's interactive viewer: a trackball camera, keys that toggle each effect and step the
// main parameters, an on-screen legend of the keys and current values, the frame time, and a key
// that saves a screenshot and the current look as a preset.
#ifndef IceViewer_h
#define IceViewer_h

#include "IceLook.h"

#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNew.h"

#include <string>

class vtkTextActor;

class IceViewer : public vtkInteractorStyleTrackballCamera
{
public:
  static IceViewer* New();
  vtkTypeMacro(IceViewer, vtkInteractorStyleTrackballCamera);

  // What the keys change, and the renderer that shows the legend.
  void Setup(const IceLook::Target& target, vtkRenderer* renderer);

  // Where the save key writes ice-view-N.png and ice-view-N.ice (default: the current folder).
  void SetOutputDirectory(const std::string& directory) { this->OutputDirectory = directory; }

  // Handles a key as if typed (what OnChar does with the interactor's key code). Returns whether
  // it is one of the viewer's keys.
  bool HandleKey(char key);

  // The legend's text and the frame-time readout, as shown.
  std::string GetLegend() const;
  std::string GetFrameTime() const;
  // The files the last save wrote (empty before the first), or why it failed.
  std::string GetLastSaved() const { return this->LastSaved; }

  void OnChar() override;

protected:
  IceViewer();
  ~IceViewer() override;

  void UpdateLegend();
  void Save();
  void Step(const std::string& name, double delta);
  void Toggle(const std::string& name);
  // Turns a count or strength off, or back on to `remembered`.
  void OffOrBack(const std::string& name, std::string& remembered);
  void Cycle(const std::string& name);
  void ShowFrameTime();

  IceLook::Target Target;
  vtkRenderer* Renderer = nullptr;
  vtkNew<vtkTextActor> Legend;
  vtkNew<vtkTextActor> FrameTime;
  bool LegendVisible = true;
  // Restored when cracks, air or bumps are switched on again.
  std::string Cracks = "8";
  std::string Air = "19";
  std::string Bumps = "0.08";
  int Saves = 0;
  std::string OutputDirectory = ".";
  std::string LastSaved;
  unsigned long EndObserver = 0;

private:
  IceViewer(const IceViewer&) = delete;
  void operator=(const IceViewer&) = delete;
};

#endif
