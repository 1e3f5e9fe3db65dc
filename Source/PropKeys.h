/**
 * The keys a prop carries for the pass in its property keys (vtkVoxelGIPass::EMISSION(),
 * DYNAMIC()), and reading and writing them, for the scan and the public setters alike: the
 * one place below the public class that knows them.
 */
#ifndef VoxelGIPropKeys_h
#define VoxelGIPropKeys_h

#include <array>

class vtkInformation;
class vtkInformationDoubleVectorKey;
class vtkInformationIntegerKey;
class vtkProp;

namespace voxelgi
{

/// Linear RGB emission of a prop (vtkVoxelGIPass::EMISSION).
vtkInformationDoubleVectorKey* EmissionKey();
/// Whether a prop is dynamic (vtkVoxelGIPass::DYNAMIC).
vtkInformationIntegerKey* DynamicKey();

/// The prop's property keys, created if it has none (VTK modifies a prop when it gets them).
vtkInformation* EnsurePropertyKeys(vtkProp* prop);

/// Set (or, for black, remove) a prop's emission key; false, leaving it, for negative or
/// non-finite values.
bool SetEmissionKey(vtkProp* prop, const double rgb[3]);

/// A prop's emission key, non-finite or negative values as 0.
std::array<double, 3> PropEmission(vtkProp* prop);

/// Mark a prop dynamic or static (no prop: nothing).
void SetDynamicKey(vtkProp* prop, bool dynamic);

/// Whether the prop is marked dynamic (SetPropDynamic).
bool PropDynamic(vtkProp* prop);

/// Whether an emission (as PropEmission returns it) emits anything.
bool Emits(const std::array<double, 3>& emission);

}

#endif
