// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceRepresentation
 * @brief   ParaView's "Ice" representation: a surface drawn by vtkIceMapper.
 *
 * A vtkGeometryRepresentationWithFaces whose mapper and LOD mapper are vtkIceMappers, so the
 * surface stays ice during interaction. ParaView delivers the surface as composite data (a
 * multiblock even for one dataset); the ice mapper draws polydata, so the blocks are merged into
 * one surface before each mapper (one ice object per representation). Colouring by an array
 * works as for "Surface": the mapper tints the ice with the mapped colours (vtkIceMapper,
 * ScalarVisibility); "Solid Color" gives the ice colour (IceColor).
 *
 * Distributed (pvbatch or pvserver on several ranks): ParaView's partition cuts objects, and
 * two-sided refraction needs each object whole. The surface is redistributed by object
 * (vtkIceRedistributeObjects: every connected surface whole on one rank, objects dealt out by
 * size) and both mappers get the bounds of the whole surface (vtkIceMapper::PlacementBounds), so
 * cracks, air and bumps are where one process puts them. With translucent geometry in the view
 * ParaView's ordered compositing moves the ice again to its spatial partition (objects cut at
 * its planes), which the order of compositing needs.
 *
 * Without a skybox (or another environment texture) the ice refracts and reflects the view's
 * background, its single colour or gradient (vtkPVIceBackgroundEnvironment, vtkPVIceMapper).
 *
 * The ice properties forward to both mappers. Two-sided refraction, cracks and air need
 * vtkIcePass, which the "Ice View" (vtkPVIceRenderView) installs; in an ordinary render view
 * the ice is one-sided and has no interior.
 */
#ifndef vtkIceRepresentation_h
#define vtkIceRepresentation_h

#include "IceViewsModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkNew.h" // for members

class vtkCompositeDataGeometryFilter;
class vtkIceMapper;
class vtkIceProperty;
class vtkIceRedistributeObjects;
class vtkPVIceBackgroundEnvironment;

class ICEVIEWS_EXPORT vtkIceRepresentation : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkIceRepresentation* New();
  vtkTypeMacro(vtkIceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The look's parameters, set on the ice property both mappers share (see vtkIceProperty for
   * meanings and ranges); TwoSidedRefraction, MaxBounces, WetBase, CrackClipping and
   * InteriorMethod on both mappers.
   */
  void SetIndexOfRefraction(double value);
  void SetFresnelPower(double value);
  void SetFresnelModel(int value);
  void SetBackNormalWeight(double value);
  void SetTwoSidedRefraction(int value);
  void SetMaxBounces(int value);
  void SetWetBase(int value);
  void SetIceColor(double red, double green, double blue);
  void SetAttenuationColor(double red, double green, double blue);
  ///@}

  ///@{
  /**
   * Absorption by the path in the ice: off (the default) gives the mappers an infinite
   * AttenuationDistance, on the distance set here (default 1). ParaView's properties cannot hold
   * the mapper's infinity, hence the switch.
   */
  void SetAbsorption(int value);
  void SetAttenuationDistance(double value);
  void SetNumberOfCracks(int value);
  void SetCrackSeed(int value);
  void SetCrackIntensity(double value);
  void SetCrackClipping(int value);
  void SetNumberOfAirPlanes(int value);
  void SetAirSeed(int value);
  void SetMilkiness(double value);
  void SetMilkyCoreRadius(double value);
  void SetBubbleDensity(double value);
  void SetIceRoughness(double value); // the ice mapper's Roughness (frost)
  void SetCrackReflection(double value);
  void SetBumpStrength(double value);
  void SetBumpScale(double value);
  void SetGlistening(int value);
  void SetGlisteningIntensity(double value);
  void SetSnowAmount(double value);
  void SetInteriorMethod(int value);
  ///@}

  /**
   * The ice mapper used when not interacting (for tests and scripts).
   */
  vtkIceMapper* GetIceMapper();

  /**
   * The ice property both mappers share.
   */
  vtkIceProperty* GetIceProperty();

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  /**
   * The redistribution of the last update (number of objects, seconds; see
   * vtkIceRedistributeObjects), for tests and benchmarks. Null with one process.
   */
  vtkIceRedistributeObjects* GetRedistribution();

protected:
  vtkIceRepresentation();
  ~vtkIceRepresentation() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkIceRepresentation(const vtkIceRepresentation&) = delete;
  void operator=(const vtkIceRepresentation&) = delete;

  template <typename Setter>
  void ForEachIceMapper(Setter setter);

  // The mappers' AttenuationDistance: infinite while Absorption is off.
  void PushAttenuationDistance();
  bool Absorption = false;
  double AttenuationDistance = 1.0;

  vtkNew<vtkCompositeDataGeometryFilter> Merge;
  vtkNew<vtkCompositeDataGeometryFilter> MergeLOD;
  // Several processes only: the merged surface and its redistribution by object.
  bool Distributed = false;
  vtkNew<vtkCompositeDataGeometryFilter> MergePiece;
  vtkNew<vtkIceRedistributeObjects> Redistribute;
  // The view's background as the ice's environment where the view has none.
  vtkNew<vtkPVIceBackgroundEnvironment> BackgroundEnvironment;
};

#endif
