// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-render's interactive viewer: a trackball camera, keys that toggle each effect and step the
// main parameters, an on-screen legend of the keys and current values, the frame time, and a key
// that saves a screenshot and the current look as a preset.
#ifndef IceViewer_h
#define IceViewer_h

#include "vtkIceLookTable.h"

#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNew.h"

#include <string>

class vtkActor;
class vtkTextActor;

class IceViewer : public vtkInteractorStyleTrackballCamera
{
public:
  static IceViewer* New();
  vtkTypeMacro(IceViewer, vtkInteractorStyleTrackballCamera);

  // What the keys change, and the renderer that shows the legend.
  void Setup(const vtkIceLookTable::Target& target, vtkRenderer* renderer);
  // Another ice (its actor's mapper a vtkIceMapper) that takes every change the keys make: the
  // ice's mirror image in its pool (IceScene::AddMirrorImage), shown while the ice shows its
  // look. After Setup.
  void Follow(vtkActor* image);

  // Where the save key writes ice-view-N.png and ice-view-N.ice (default: the current folder).
  void SetOutputDirectory(const std::string& directory) { this->OutputDirectory = directory; }

  // Handles a key as if typed (what OnChar does with the interactor's key code). Returns whether
  // it is one of the viewer's keys.
  bool HandleKey(char key);

  // The legend's whole text (the keys and current values) and the frame-time readout.
  std::string GetLegend() const;
  std::string GetFrameTime() const;
  // The files the last save wrote (empty before the first), or why it failed.
  std::string GetLastSaved() const { return this->LastSaved; }

  // What the legend shows, chosen at each render for the window's size: the whole list, or in a
  // window where the list would cover more than MaximumLegendShare of it, one line ("h  keys");
  // 'h' switches to the other (in a large window: to nothing).
  enum LegendKind
  {
    LegendNone,
    LegendHint,
    LegendFull
  };
  LegendKind GetLegendShown() const { return this->Shown; }
  // The legend's font size in pixels (14 at 1024x768, with the window's size, at least 8).
  int GetLegendFontSize() const;
  // The share of the window the shown legend covers, at the last render.
  double GetLegendShare() const { return this->Share; }
  static constexpr double MaximumLegendShare = 0.15;

  void OnChar() override;

protected:
  IceViewer();
  ~IceViewer() override;

  void UpdateLegend();
  // Sizes the legend for the renderer's size and picks what it shows (before each render).
  void FitLegend();
  void Save();
  void Step(const std::string& name, double delta);
  void Toggle(const std::string& name);
  // Turns a count or strength off, or back on to `remembered`.
  void OffOrBack(const std::string& name, std::string& remembered);
  void Cycle(const std::string& name);
  void ShowFrameTime();

  // Sets `name` on the ice and on the one that follows it.
  void Set(const std::string& name, const std::string& value);

  vtkIceLookTable::Target Target;
  vtkIceLookTable::Target Mirror;
  vtkActor* MirrorImage = nullptr;
  vtkRenderer* Renderer = nullptr;
  vtkNew<vtkTextActor> Legend;
  vtkNew<vtkTextActor> FrameTime;
  // Flipped by 'h': the other of the two choices FitLegend makes.
  bool LegendToggled = false;
  // The legend and readout left out (Save's picture).
  bool TextHidden = false;
  std::string LegendText;
  LegendKind Shown = LegendFull;
  double Share = 0.0;
  // Restored when cracks, air or bumps are switched on again.
  std::string Cracks = "8";
  std::string Air = "19";
  std::string Bumps = "0.08";
  int Saves = 0;
  std::string OutputDirectory = ".";
  std::string LastSaved;
  unsigned long EndObserver = 0;
  unsigned long StartObserver = 0;

private:
  IceViewer(const IceViewer&) = delete;
  void operator=(const IceViewer&) = delete;
};

#endif
