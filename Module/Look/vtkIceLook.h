// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIceLook
 * @brief   The look's settings by name, for wrapped languages.
 *
 * vtkIceLook gives Python (and any wrapped language) the one table of the look's settings that
 * ice-render's options, its preset files and its viewer use (vtkIceLookTable.h): every
 * vtkIceMapper and vtkIceCubeMapPass parameter and the camera, by name ("eta", "cracks",
 * "cube-map", ...), with its kind, help, range, default and accepted names, and Apply/Value to
 * set and read one on a scene. Values are text as on ice-render's command line: numbers,
 * "on"/"off", a choice's name, "x,y,z". All methods are static.
 *
 * @code{.py}
 * for i in range(vtkice.vtkIceLook.GetNumberOfSettings()):
 *     print(vtkice.vtkIceLook.GetName(i), vtkice.vtkIceLook.GetHelp(i))
 * problem = vtkice.vtkIceLook.Apply(mapper, icePass, cubeMapPass, camera, "cracks", "8")
 * @endcode
 */

#ifndef vtkIceLook_h
#define vtkIceLook_h

#include "LookIceModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string

class vtkCamera;
class vtkIceCubeMapPass;
class vtkIceMapper;
class vtkIcePass;
class vtkToneMappingPass;

class LOOKICE_EXPORT vtkIceLook : public vtkObject
{
public:
  static vtkIceLook* New();
  vtkTypeMacro(vtkIceLook, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Number of settings; they are numbered 0..n-1 in the order ice-render --help lists them.
   */
  static int GetNumberOfSettings();

  /**
   * Index of the setting `name`, or -1.
   */
  static int FindSetting(const char* name);

  ///@{
  /**
   * The i-th setting's name, its kind ("number", "integer", "switch", "choice" or "vector") and
   * its help line; nullptr for an index out of range.
   */
  static const char* GetName(int i);
  static const char* GetKind(int i);
  static const char* GetHelp(int i);
  ///@}

  /**
   * Whether the i-th setting moves the camera (not part of a look: a preset names it only when
   * it was given).
   */
  static bool IsCameraSetting(int i);

  /**
   * The setting whose value the i-th gives in other units ("eta" is 1 / "ior"), or null: a user
   * interface shows one of the two; written presets leave the synonym out.
   */
  static const char* GetSynonymOf(int i);

  ///@{
  /**
   * The library's range of a "number" or "integer" setting; 0 for other kinds.
   */
  static double GetMinimum(int i);
  static double GetMaximum(int i);
  ///@}

  ///@{
  /**
   * The names a "choice" setting accepts, in the order of the library's enum (0 for other kinds).
   */
  static int GetNumberOfChoices(int i);
  static const char* GetChoice(int i, int choice);
  ///@}

  /**
   * The i-th setting's value when nothing sets it (the library's defaults, the dynamic cube map
   * on); empty for the camera settings, which a scene chooses to frame its model.
   */
  static std::string GetDefault(int i);

  /**
   * Sets `name` to `value` on a scene: its ice mapper, ice pass, the pass's cube-map pass (which
   * "cube-map" switches on and off) and camera; none may be nullptr. Returns an empty string, or
   * why the value is refused (with the range or the accepted names): out-of-range values are
   * refused, not clamped, and nothing changes.
   */
  static std::string Apply(vtkIceMapper* mapper, vtkIcePass* pass, vtkIceCubeMapPass* cubeMaps,
    vtkCamera* camera, const char* name, const char* value);

  /**
   * The current value of `name` on a scene, as Apply takes it; empty for an unknown name or a
   * nullptr.
   */
  static std::string GetValue(vtkIceMapper* mapper, vtkIcePass* pass, vtkIceCubeMapPass* cubeMaps,
    vtkCamera* camera, const char* name);

  /**
   * Reads a preset file (ice-render's "NAME = VALUE" lines) and applies it to a scene in order.
   * Returns an empty string, or the first problem with the file's line number; a file with a
   * problem changes nothing.
   */
  static std::string ApplyPreset(vtkIceMapper* mapper, vtkIcePass* pass,
    vtkIceCubeMapPass* cubeMaps, vtkCamera* camera, const char* path);

  ///@{
  /**
   * The same for a scene whose ice pass is the delegate of a vtkToneMappingPass, which
   * "tone-mapping" and "exposure" set (without it they are refused). ResetToneMapping puts such a
   * pass in the state of no tone mapping; AsksForToneMapping says whether its look needs it in the
   * renderer's passes.
   */
  static std::string Apply(vtkIceMapper* mapper, vtkIcePass* pass, vtkIceCubeMapPass* cubeMaps,
    vtkCamera* camera, vtkToneMappingPass* toneMapping, const char* name, const char* value);
  static std::string GetValue(vtkIceMapper* mapper, vtkIcePass* pass, vtkIceCubeMapPass* cubeMaps,
    vtkCamera* camera, vtkToneMappingPass* toneMapping, const char* name);
  static std::string ApplyPreset(vtkIceMapper* mapper, vtkIcePass* pass,
    vtkIceCubeMapPass* cubeMaps, vtkCamera* camera, vtkToneMappingPass* toneMapping,
    const char* path);
  static void ResetToneMapping(vtkToneMappingPass* toneMapping);
  static bool AsksForToneMapping(vtkToneMappingPass* toneMapping);
  ///@}

protected:
  vtkIceLook() = default;
  ~vtkIceLook() override = default;

private:
  vtkIceLook(const vtkIceLook&) = delete;
  void operator=(const vtkIceLook&) = delete;
};

#endif // vtkIceLook_h
