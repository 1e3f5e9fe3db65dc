/**
 * ImageSliceProxies: image slices (vtkImageActor, vtkImageSlice with a vtkImageSliceMapper,
 * the planes of a medical viewer) voxelized as the textured quads VTK draws them as. For each
 * slice a proxy actor holds the displayed slice as a quad in the image's physical space with
 * the slice's matrix, textured with the colours VTK shows (the slice property's lookup table,
 * or its window and level), so that the voxelization, shadow maps and the scan treat it as
 * any textured actor. The proxy is rebuilt only when the slice, its mapper, input, property
 * or lookup table changed. GL-free.
 */
#ifndef VoxelGIImageSliceProxies_h
#define VoxelGIImageSliceProxies_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkMTimeType

#include <set>
#include <string>
#include <unordered_map>

class vtkActor;
class vtkImageData;
class vtkImageSlice;
class vtkPolyData;
class vtkProp;
class vtkTexture;

namespace voxelgi
{

class ImageSliceProxies
{
public:
  /// Why the slice cannot be voxelized (empty: it can): not a vtkImageSliceMapper, or
  /// translucent.
  static std::string LeftOutReason(vtkImageSlice* slice);
  /// The up-to-date proxy of `slice` (LeftOutReason() empty) whose signature the scan found
  /// (PropReader::PropSignature), or null with `reason` when its displayed slice has no area
  /// or no scalars.
  vtkActor* Update(vtkImageSlice* slice, vtkMTimeType signature, std::string& reason);
  /// Drop the proxies of slices not in `kept`.
  void Retain(const std::set<vtkProp*>& kept);

private:
  struct Proxy
  {
    vtkSmartPointer<vtkActor> Actor;
    vtkMTimeType Synced = 0;
  };
  /// The displayed slice's index extent (one flat axis) and its in-plane axes and sizes.
  struct SliceExtent
  {
    int Extent[6];
    int Flat, U, V;
    int NU, NV;
  };
  /// Build the quad and its texture from the slice as it is now.
  static bool Build(vtkImageSlice* slice, vtkActor* proxy, std::string& reason);
  /// False when the displayed slice has no area.
  static bool DisplayedExtent(vtkImageSlice* slice, vtkImageData* image, SliceExtent& extent);
  static vtkSmartPointer<vtkTexture> Texture(
    vtkImageSlice* slice, vtkImageData* image, const SliceExtent& extent);
  static vtkSmartPointer<vtkPolyData> Quad(vtkImageData* image, const SliceExtent& extent);

  std::unordered_map<vtkImageSlice*, Proxy> Proxies;
};

}

#endif
