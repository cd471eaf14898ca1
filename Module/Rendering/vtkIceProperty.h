// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceProperty
 * @brief   The look of ice: its optics, cracks, air, surface and glistening.
 *
 * vtkIceProperty holds the material parameters of vtkIceMapper, as vtkProperty holds a surface's
 * for VTK's mappers: set one on a mapper (vtkIceMapper::SetIceProperty), share it between
 * mappers to give several objects the same ice, change it and every mapper using it draws the
 * new look at the next render. Names follow glTF where it has one (IndexOfRefraction,
 * AttenuationColor, AttenuationDistance, Roughness).
 *
 * How the ice is drawn (two-sided method, interior method, crack clipping, debug views, culling)
 * stays on the mapper. The mapper's own setters of these parameters (vtkIceMapper::SetRoughness
 * and the others) set its property's.
 *
 * Floating-point parameters are clamped to the ranges their Get...MinValue/MaxValue give; NaN
 * is refused with a warning naming the parameter (vtkSetClampMacro would store it).
 */
#ifndef vtkIceProperty_h
#define vtkIceProperty_h

#include "RenderingIceModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members

#include <array> // for GetShaderValues

class vtkTexture;

class RENDERINGICE_EXPORT vtkIceProperty : public vtkObject
{
public:
  static vtkIceProperty* New();
  vtkTypeMacro(vtkIceProperty, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Copies every parameter of `other` (the normal map shared, not copied).
   */
  void DeepCopy(vtkIceProperty* other);

  ///@{
  /**
   * The ice's index of refraction, as glTF's KHR_materials_ior means it (relative to the air
   * around it). Default 1.31, ice's. The ratio the optics use (eta of eq 2, RefractionRatio) is
   * its inverse: setting one sets the other, and each reads back what was set. Clamped to
   * [0.05, 20]; 1 lets rays pass undeflected.
   */
  virtual void SetIndexOfRefraction(double ior);
  virtual double GetIndexOfRefractionMinValue() { return 0.05; }
  virtual double GetIndexOfRefractionMaxValue() { return 20.0; }
  vtkGetMacro(IndexOfRefraction, double);
  ///@}

  ///@{
  /**
   * Ratio of refraction indices, from / to (eta of eq 2): 1 / IndexOfRefraction, which it sets.
   * Default 1 / 1.31. Clamped to [0.05, 20].
   */
  virtual void SetRefractionRatio(double eta);
  virtual double GetRefractionRatioMinValue() { return 0.05; }
  virtual double GetRefractionRatioMaxValue() { return 20.0; }
  vtkGetMacro(RefractionRatio, double);
  ///@}

  ///@{
  /**
   * Absorption by the distance the light travels in the ice (Beer-Lambert), with glTF
   * KHR_materials_volume's meaning: white light that has travelled AttenuationDistance in the
   * ice has the colour AttenuationColor. Defaults: white and infinity (no absorption). The
   * distance is the refracted ray's path from the front face to the back face behind it, so it
   * needs vtkIcePass on the renderer (without it the ice does not absorb, and the mapper says
   * so once). Colour components are clamped to [0, 1], the distance to [1e-6, infinity].
   */
  virtual void SetAttenuationColor(double red, double green, double blue);
  virtual void SetAttenuationColor(const double color[3])
  {
    this->SetAttenuationColor(color[0], color[1], color[2]);
  }
  vtkGetVector3Macro(AttenuationColor, double);
  virtual void SetAttenuationDistance(double distance);
  virtual double GetAttenuationDistanceMinValue() { return 1.0e-6; }
  virtual double GetAttenuationDistanceMaxValue();
  vtkGetMacro(AttenuationDistance, double);
  ///@}

  /**
   * Whether the ice absorbs: a finite AttenuationDistance and an AttenuationColor below white.
   */
  bool Absorbs() const;

  ///@{
  /**
   * Exponent of the Fresnel approximation f = (1 - |e.n|)^P (eq 4). Default 3. Larger values
   * show less reflection away from the silhouette. Clamped to [0, 1e6].
   */
  virtual void SetFresnelPower(double power);
  virtual double GetFresnelPowerMinValue() { return 0.0; }
  virtual double GetFresnelPowerMaxValue() { return 1.0e6; }
  vtkGetMacro(FresnelPower, double);
  ///@}

  enum FresnelModels
  {
    FresnelPaper = 0,     // eq 4's power of 1 - |e.n|, FresnelPower
    FresnelDielectric = 1 // Fresnel's equations for unpolarised light at the IndexOfRefraction
  };

  ///@{
  /**
   * How much of the light meeting the ice is reflected. FresnelPaper (default): the paper's eq 4,
   * (1 - |e.n|)^FresnelPower, evaluated per vertex. FresnelDielectric: Fresnel's equations of a
   * clean air-to-ice interface of the IndexOfRefraction, per fragment (2 % head-on for ice,
   * rising to all of it at grazing angles), what a path tracer computes; FresnelPower is then not
   * used.
   */
  vtkSetClampMacro(FresnelModel, int, FresnelPaper, FresnelDielectric);
  vtkGetMacro(FresnelModel, int);
  void SetFresnelModelToPaper() { this->SetFresnelModel(FresnelPaper); }
  void SetFresnelModelToDielectric() { this->SetFresnelModel(FresnelDielectric); }
  ///@}

  ///@{
  /**
   * Weight a of the back-face normal in the blended refraction normal (eq 1; the mapper's
   * TwoSidedBlendedNormals). Default 0.33; clamped to [0, 1].
   */
  virtual void SetBackNormalWeight(double weight);
  virtual double GetBackNormalWeightMinValue() { return 0.0; }
  virtual double GetBackNormalWeightMaxValue() { return 1.0; }
  vtkGetMacro(BackNormalWeight, double);
  ///@}

  ///@{
  /**
   * Tint multiplied into the ice colour, each component clamped to [0, 1]. Default white. When
   * the mapper colours by scalars (vtkIceMapper, ScalarVisibility), the mapped colours replace it.
   */
  virtual void SetIceColor(double red, double green, double blue);
  virtual void SetIceColor(const double color[3])
  {
    this->SetIceColor(color[0], color[1], color[2]);
  }
  vtkGetVector3Macro(IceColor, double);
  ///@}

  ///@{
  /**
   * Frost: how rough the surface is, in [0, 1] (glTF's roughness: GGX with alpha = roughness^2).
   * Reflection and refraction both show the environment averaged over the rough surface's lobe
   * (the environment prefiltered once per change of it, static or dynamic), as cold ice covered
   * in small crystals does. 0 (the default): a mirror-smooth surface, the paper's look.
   */
  virtual void SetRoughness(double roughness);
  virtual double GetRoughnessMinValue() { return 0.0; }
  virtual double GetRoughnessMaxValue() { return 1.0; }
  vtkGetMacro(Roughness, double);
  ///@}

  ///@{
  /**
   * Number of crack surfaces inside the ice (drawn with vtkIcePass). Default 2; clamped to
   * [0, 1000].
   */
  vtkSetClampMacro(NumberOfCracks, int, 0, 1000);
  vtkGetMacro(NumberOfCracks, int);
  ///@}

  ///@{
  /**
   * Seed of the cracks' models, rotations and positions: the same seed gives the same cracks.
   * Default 1.
   */
  vtkSetMacro(CrackSeed, int);
  vtkGetMacro(CrackSeed, int);
  ///@}

  ///@{
  /**
   * Brightness of the cracks' highlights. Default 1; clamped to [0, 100].
   */
  virtual void SetCrackIntensity(double intensity);
  virtual double GetCrackIntensityMinValue() { return 0.0; }
  virtual double GetCrackIntensityMaxValue() { return 100.0; }
  vtkGetMacro(CrackIntensity, double);
  ///@}

  ///@{
  /**
   * Cracks as sheets: how much of the reflectance of a thin gap of air in the ice (Fresnel's,
   * all of it at glancing angles: total internal reflection) a crack mirrors of the environment,
   * its outline whitening with it. 0: the highlights alone, the paper's look. Default 0.4;
   * clamped to [0, 1]. Drawn by the mapper's screen-space interior with vtkIcePass.
   */
  virtual void SetCrackReflection(double reflection);
  virtual double GetCrackReflectionMinValue() { return 0.0; }
  virtual double GetCrackReflectionMaxValue() { return 1.0; }
  vtkGetMacro(CrackReflection, double);
  ///@}

  ///@{
  /**
   * Number of air-bubble planes inside the ice (drawn with vtkIcePass). Default 19, as in the
   * paper's measurements; clamped to [0, 1000]. 0 turns the air off.
   */
  vtkSetClampMacro(NumberOfAirPlanes, int, 0, 1000);
  vtkGetMacro(NumberOfAirPlanes, int);
  ///@}

  ///@{
  /**
   * Seed of the air planes' positions, orientations and images. Default 1.
   */
  vtkSetMacro(AirSeed, int);
  vtkGetMacro(AirSeed, int);
  ///@}

  ///@{
  /**
   * How white and cloudy the air makes the ice: 0 sparse clear bubbles, 1 milky. Default 0.5.
   */
  virtual void SetMilkiness(double milkiness);
  virtual double GetMilkinessMinValue() { return 0.0; }
  virtual double GetMilkinessMaxValue() { return 1.0; }
  vtkGetMacro(Milkiness, double);
  ///@}

  ///@{
  /**
   * A milky core: air gathered where the ice froze last, around the centre of its bounds, as a
   * cloud that whitens what is seen through it (by Milkiness: a ray through its centre at
   * Milkiness 1 loses 98 % of what is behind) and draws the air planes' bubbles towards it. Its
   * radius is this fraction of the ice's half size along each axis; the cloud thins smoothly
   * beyond it. 0 (the default): no core. Clamped to [0, 10]. Drawn by the mapper's screen-space
   * interior with vtkIcePass.
   */
  virtual void SetMilkyCoreRadius(double radius);
  virtual double GetMilkyCoreRadiusMinValue() { return 0.0; }
  virtual double GetMilkyCoreRadiusMaxValue() { return 10.0; }
  vtkGetMacro(MilkyCoreRadius, double);
  ///@}

  /**
   * Whether there is a milky core: MilkyCoreRadius and Milkiness above 0.
   */
  bool HasMilkyCore() const { return this->MilkyCoreRadius > 0.0 && this->Milkiness > 0.0; }

  ///@{
  /**
   * Small air bubbles frozen into the ice, drawn one by one as white specks of mixed sizes (small
   * ones most), a few in vertical streams, fading with their depth in the ice: 0 (the default)
   * none, 1 a dense cloud. They gather where the milky core is (its centre and radius; without a
   * core, in the middle 0.6 of the ice's half size) and thin out gradually beyond it, so they
   * give the core its grain. Clamped to [0, 1]. Drawn by the mapper's screen-space interior with
   * vtkIcePass.
   */
  virtual void SetBubbleDensity(double density);
  virtual double GetBubbleDensityMinValue() { return 0.0; }
  virtual double GetBubbleDensityMaxValue() { return 1.0; }
  vtkGetMacro(BubbleDensity, double);
  ///@}

  ///@{
  /**
   * A bumpy surface: how far the normal tilts (0 = smooth, the paper's clean optics) and the size
   * of a bump as a fraction of the ice's largest extent. The bumps are fixed to the model, so they
   * do not swim when the camera moves, and they drive reflection, refraction and Fresnel.
   * Defaults 0.08 and 0.15.
   */
  virtual void SetBumpStrength(double bumpStrength);
  virtual double GetBumpStrengthMinValue() { return 0.0; }
  virtual double GetBumpStrengthMaxValue() { return 10.0; }
  vtkGetMacro(BumpStrength, double);
  virtual void SetBumpScale(double bumpScale);
  virtual double GetBumpScaleMinValue() { return 1.0e-4; }
  virtual double GetBumpScaleMaxValue() { return 100.0; }
  vtkGetMacro(BumpScale, double);
  ///@}

  ///@{
  /**
   * A tangent-space normal map (RGB, repeat on) used instead of the procedural bumps, projected
   * on the three model planes; BumpStrength scales it and BumpScale is the size of one repeat.
   */
  void SetNormalMap(vtkTexture* texture);
  vtkTexture* GetNormalMap();
  ///@}

  ///@{
  /**
   * Glistening ice and snow (Liquidiced): direct light from the scene's lights (Phong with a
   * broad, soft specular on a subtle wavy bump), rim light, and two layers of crack glints (one
   * roughly parallel to the surface, one of any orientation) from a random normal texture, crisp
   * at any distance. Added to the ice; with SnowAmount 1 the surface is snow instead. Default off.
   */
  vtkSetMacro(Glistening, bool);
  vtkGetMacro(Glistening, bool);
  vtkBooleanMacro(Glistening, bool);
  ///@}

  ///@{
  /**
   * With Glistening: size of a crack cell in the input's units. Default 0.03; clamped to
   * [1e-6, 1e6].
   */
  virtual void SetGlisteningScale(double glisteningScale);
  virtual double GetGlisteningScaleMinValue() { return 1.0e-6; }
  virtual double GetGlisteningScaleMaxValue() { return 1.0e6; }
  vtkGetMacro(GlisteningScale, double);
  ///@}

  ///@{
  /**
   * With Glistening: brightness of the glints. Default 1; clamped to [0, 100].
   */
  virtual void SetGlisteningIntensity(double glisteningIntensity);
  virtual double GetGlisteningIntensityMinValue() { return 0.0; }
  virtual double GetGlisteningIntensityMaxValue() { return 100.0; }
  vtkGetMacro(GlisteningIntensity, double);
  ///@}

  ///@{
  /**
   * With Glistening: gain of the glints where the view looks along a light's direction (the light
   * behind the viewer), where the surface specular and the parallel crack layer are missing.
   * Default 2 (doubled, as in Liquidiced); 1 turns the intensification off. Clamped to [1, 10].
   */
  virtual void SetGlisteningAlignmentGain(double glisteningAlignmentGain);
  virtual double GetGlisteningAlignmentGainMinValue() { return 1.0; }
  virtual double GetGlisteningAlignmentGainMaxValue() { return 10.0; }
  vtkGetMacro(GlisteningAlignmentGain, double);
  ///@}

  ///@{
  /**
   * With Glistening: 0 gives ice, 1 snow (white, diffuse), values between blend the two looks.
   * Default 0; clamped to [0, 1]. Snow without Glistening shows nothing: the mapper says so once.
   */
  virtual void SetSnowAmount(double snowAmount);
  virtual double GetSnowAmountMinValue() { return 0.0; }
  virtual double GetSnowAmountMaxValue() { return 1.0; }
  vtkGetMacro(SnowAmount, double);
  ///@}

#ifndef __VTK_WRAP__
  /**
   * What the surface's shaders read of the look directly: a uniform's name and its 1 or 3 float
   * values (Optional: declared by the programs of some parts only). The code that owns a program
   * sets them (vtkIcePropertyUniforms); a parameter of this kind is added here alone, with no
   * OpenGL in the property.
   */
  struct ShaderValue
  {
    const char* Name;
    int Components;
    float Value[3];
    bool Optional;
  };
  std::array<ShaderValue, 8> GetShaderValues() const; // no allocation: called every draw
#endif

protected:
  vtkIceProperty();
  ~vtkIceProperty() override;

  double IndexOfRefraction = 1.31;
  double RefractionRatio = 1.0 / 1.31;
  double AttenuationColor[3] = { 1.0, 1.0, 1.0 };
  double AttenuationDistance;
  double FresnelPower = 3.0;
  int FresnelModel = FresnelPaper;
  double BackNormalWeight = 0.33;
  double IceColor[3] = { 1.0, 1.0, 1.0 };
  double Roughness = 0.0;
  int NumberOfCracks = 2;
  int CrackSeed = 1;
  double CrackIntensity = 1.0;
  double CrackReflection = 0.4;
  int NumberOfAirPlanes = 19;
  int AirSeed = 1;
  double Milkiness = 0.5;
  double MilkyCoreRadius = 0.0;
  double BubbleDensity = 0.0;
  double BumpStrength = 0.08;
  double BumpScale = 0.15;
  vtkSmartPointer<vtkTexture> NormalMap;
  bool Glistening = false;
  double GlisteningScale = 0.03;
  double GlisteningIntensity = 1.0;
  double GlisteningAlignmentGain = 2.0;
  double SnowAmount = 0.0;

private:
  vtkIceProperty(const vtkIceProperty&) = delete;
  void operator=(const vtkIceProperty&) = delete;
};

#endif
