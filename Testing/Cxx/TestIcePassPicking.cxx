// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// Hardware picking and selection with vtkIcePass: a cone (plain VTK) and an ice sphere. With the
// pass, vtkPropPicker picks the same prop under each of a grid of pixels as without it (the ice
// included), vtkRenderedAreaPicker finds the same props in each half of the window, a pick list
// is honoured, and vtkHardwareSelector over the whole viewport finds the same props and the same
// number of cells. Without the pass taking over the selection, nothing was picked.
#include "IceTestUtilities.h"
#include "vtkIceCubeMapSource.h"
#include "vtkIceMapper.h"
#include "vtkIcePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkHardwareSelector.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp3DCollection.h"
#include "vtkPropPicker.h"
#include "vtkRenderedAreaPicker.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <algorithm>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
struct Scene
{
  Scene(bool withPass)
  {
    this->Environment = IceTest::MakeCubeMap(vtkIceCubeMapSource::DirectionTest, 64);
    this->Renderer->SetEnvironmentTexture(this->Environment);
    vtkNew<vtkConeSource> cone;
    vtkNew<vtkPolyDataMapper> coneMapper;
    coneMapper->SetInputConnection(cone->GetOutputPort());
    this->Cone->SetMapper(coneMapper);
    this->Cone->SetPosition(-1.0, 0.0, 0.0);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(0.6);
    vtkNew<vtkIceMapper> iceMapper;
    iceMapper->SetInputConnection(sphere->GetOutputPort());
    iceMapper->GetIceProperty()->SetNumberOfCracks(2);
    this->Ice->SetMapper(iceMapper);
    this->Ice->SetPosition(1.0, 0.0, 0.0);
    this->Renderer->AddActor(this->Cone);
    this->Renderer->AddActor(this->Ice);
    if (withPass)
    {
      this->Renderer->SetPass(this->Pass);
    }
    this->Window->SetSize(200, 120);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 5.0);
    this->Renderer->ResetCameraClippingRange();
    this->Window->Render();
  }
  // 0 nothing, 1 the cone, 2 the ice, at each pixel of a 10-pixel grid; with `onlyCone`, the
  // picker's pick list holds the cone alone.
  std::vector<int> PickGrid(bool onlyCone = false)
  {
    std::vector<int> picked;
    vtkNew<vtkPropPicker> picker;
    if (onlyCone)
    {
      picker->AddPickList(this->Cone);
      picker->PickFromListOn();
    }
    for (int y = 5; y < 120; y += 10)
    {
      for (int x = 5; x < 200; x += 10)
      {
        picker->Pick(x, y, 0.0, this->Renderer); // honours the pick list
        vtkProp* prop = picker->GetViewProp();
        picked.push_back(prop == this->Cone ? 1 : prop == this->Ice ? 2 : prop ? 3 : 0);
      }
    }
    return picked;
  }
  // Props vtkRenderedAreaPicker finds in the left and right halves (bit 1 cone, bit 2 ice).
  std::vector<int> AreaPicks()
  {
    std::vector<int> found;
    vtkNew<vtkRenderedAreaPicker> picker;
    for (int half = 0; half < 2; ++half)
    {
      picker->AreaPick(100 * half, 0, 100 * half + 99, 119, this->Renderer);
      int bits = 0;
      vtkProp3DCollection* props = picker->GetProp3Ds();
      props->InitTraversal();
      while (vtkProp3D* prop = props->GetNextProp3D())
      {
        bits |= prop == this->Cone ? 1 : prop == this->Ice ? 2 : 4;
      }
      found.push_back(bits);
    }
    return found;
  }
  // Cells selected over the whole viewport, by prop (1 cone, 2 ice).
  std::map<int, vtkIdType> SelectAll()
  {
    vtkNew<vtkHardwareSelector> selector;
    selector->SetRenderer(this->Renderer);
    selector->SetArea(0, 0, 199, 119);
    selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
    vtkSmartPointer<vtkSelection> selection;
    selection.TakeReference(selector->Select());
    std::map<int, vtkIdType> cells;
    for (unsigned int i = 0; selection && i < selection->GetNumberOfNodes(); ++i)
    {
      vtkSelectionNode* node = selection->GetNode(i);
      vtkObjectBase* prop = node->GetProperties()->Get(vtkSelectionNode::PROP());
      const int id = prop == this->Cone ? 1 : prop == this->Ice ? 2 : 3;
      cells[id] += node->GetSelectionList() ? node->GetSelectionList()->GetNumberOfTuples() : 0;
    }
    return cells;
  }
  vtkSmartPointer<vtkTexture> Environment;
  vtkNew<vtkActor> Cone;
  vtkNew<vtkActor> Ice;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkIcePass> Pass;
  vtkNew<vtkRenderWindow> Window;
};

std::string Describe(const std::map<int, vtkIdType>& cells)
{
  std::string text;
  for (const auto& entry : cells)
  {
    text += (entry.first == 1      ? "cone "
                : entry.first == 2 ? "ice "
                                   : "other ") +
      std::to_string(entry.second) + " cells; ";
  }
  return text.empty() ? "nothing" : text;
}
}

int TestIcePassPicking(int, char*[])
{
  Scene plain(false);
  Scene withPass(true);
  const std::vector<int> expected = plain.PickGrid();
  const std::vector<int> picked = withPass.PickGrid();
  size_t cone = 0;
  size_t ice = 0;
  size_t same = 0;
  for (size_t i = 0; i < expected.size(); ++i)
  {
    cone += expected[i] == 1 ? 1 : 0;
    ice += expected[i] == 2 ? 1 : 0;
    same += expected[i] == picked[i] ? 1 : 0;
  }
  bool ok = cone > 3 && ice > 3 && same == expected.size();
  std::cout << (ok ? "ok   " : "FAIL ") << "vtkPropPicker on " << expected.size() << " pixels ("
            << cone << " on the cone, " << ice << " on the ice without the pass): " << same
            << " picks the same with vtkIcePass\n";

  const std::map<int, vtkIdType> expectedCells = plain.SelectAll();
  const std::map<int, vtkIdType> cells = withPass.SelectAll();
  const bool selected = expectedCells.size() == 2 && cells == expectedCells;
  std::cout << (selected ? "ok   " : "FAIL ")
            << "vtkHardwareSelector over the viewport: without the pass " << Describe(expectedCells)
            << "with it " << Describe(cells) << "\n";
  const std::vector<int> expectedAreas = plain.AreaPicks();
  const std::vector<int> areas = withPass.AreaPicks();
  const bool areaOk = expectedAreas == std::vector<int>{ 1, 2 } && areas == expectedAreas;
  std::cout << (areaOk ? "ok   " : "FAIL ")
            << "vtkRenderedAreaPicker, left and right halves: " << areas[0] << ", " << areas[1]
            << " with vtkIcePass (1 cone, 2 ice; without it " << expectedAreas[0] << ", "
            << expectedAreas[1] << ")\n";
  ok = areaOk && ok;
  // Last: a pick list stays on the renderer after the pick (VTK 9.1).
  const std::vector<int> expectedCone = plain.PickGrid(true);
  const std::vector<int> pickedCone = withPass.PickGrid(true);
  const bool list = expectedCone == pickedCone &&
    std::count(expectedCone.begin(), expectedCone.end(), 2) == 0 &&
    std::count(expectedCone.begin(), expectedCone.end(), 1) >= static_cast<long>(cone);
  std::cout << (list ? "ok   " : "FAIL ") << "with a pick list of the cone: the same picks "
            << (expectedCone == pickedCone ? "" : "NOT ") << "with vtkIcePass, the ice never\n";
  ok = list && ok;

  return ok && selected ? EXIT_SUCCESS : EXIT_FAILURE;
}
