#include "PropKeys.h"

#include "vtkVoxelGIPass.h"

#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkNew.h"
#include "vtkProp.h"

#include <algorithm>
#include <cmath>

namespace voxelgi
{

// The keys are the pass's static members (VTK's key macros register them for cleanup).
vtkInformationDoubleVectorKey* EmissionKey()
{
  return vtkVoxelGIPass::EMISSION();
}

vtkInformationIntegerKey* DynamicKey()
{
  return vtkVoxelGIPass::DYNAMIC();
}

vtkInformation* EnsurePropertyKeys(vtkProp* prop)
{
  if (!prop->GetPropertyKeys())
  {
    vtkNew<vtkInformation> info;
    prop->SetPropertyKeys(info);
  }
  return prop->GetPropertyKeys();
}

bool SetEmissionKey(vtkProp* prop, const double rgb[3])
{
  if (!std::all_of(rgb, rgb + 3, [](double v) { return std::isfinite(v) && v >= 0.0; }))
  {
    return false;
  }
  vtkInformation* info = EnsurePropertyKeys(prop);
  if (rgb[0] == 0.0 && rgb[1] == 0.0 && rgb[2] == 0.0)
  {
    info->Remove(EmissionKey());
  }
  else
  {
    info->Set(EmissionKey(), rgb, 3);
  }
  return true;
}

std::array<double, 3> PropEmission(vtkProp* prop)
{
  std::array<double, 3> e{ { 0.0, 0.0, 0.0 } };
  vtkInformation* info = prop->GetPropertyKeys();
  if (info && info->Has(EmissionKey()))
  {
    const double* v = info->Get(EmissionKey());
    for (int c = 0; c < 3; ++c)
    {
      // Keys set around SetPropEmission() may still hold bad values: never let them through.
      e[c] = std::isfinite(v[c]) ? std::max(v[c], 0.0) : 0.0;
    }
  }
  return e;
}

void SetDynamicKey(vtkProp* prop, bool dynamic)
{
  if (prop)
  {
    EnsurePropertyKeys(prop)->Set(DynamicKey(), dynamic ? 1 : 0);
  }
}

bool PropDynamic(vtkProp* prop)
{
  vtkInformation* info = prop->GetPropertyKeys();
  return info && info->Has(DynamicKey()) && info->Get(DynamicKey());
}

bool Emits(const std::array<double, 3>& emission)
{
  return emission[0] > 0.0 || emission[1] > 0.0 || emission[2] > 0.0;
}

}
