#include "PropReader.h"

#include "SceneBuffers.h"

#include "ImageSliceProxies.h"
#include "ImposterProxies.h"
#include "PropKeys.h"
#include "VolumeVoxels.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkAssembly.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCullerCollection.h"
#include "vtkDataSetMapper.h"
#include "vtkFrustumCoverageCuller.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageMapper3D.h"
#include "vtkImageSlice.h"
#include "vtkLinearTransform.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPolyData.h"
#include "vtkProp3DCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProperty.h"
#include "vtkTexture.h"
#include "vtkUniforms.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cstring>

namespace voxelgi
{

bool PointsAndLinesOnly(vtkDataObject* data)
{
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    return poly->GetNumberOfPolys() + poly->GetNumberOfStrips() == 0;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return false;
  }
  vtkSmartPointer<vtkCompositeDataIterator> block;
  block.TakeReference(composite->NewIterator());
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
  {
    if (!PointsAndLinesOnly(block->GetCurrentDataObject()))
    {
      return false;
    }
  }
  return true;
}

namespace
{
/// Why an actor drawing `data` with `property` shows no area to voxelize (null: it does,
/// or it draws plain points and lines, also as a wireframe, which take no light worth a notice): points and
/// wireframes, and points and lines drawn as imposter spheres and tubes (no triangles).
const char* NoAreaReason(vtkProperty* property, vtkDataObject* data)
{
  const int representation = property->GetRepresentation();
  const bool linesOnly = PointsAndLinesOnly(data);
  if (representation == VTK_SURFACE && !linesOnly)
  {
    return nullptr;
  }
  if (representation == VTK_POINTS)
  {
    return property->GetRenderPointsAsSpheres() ? "points drawn as spheres: imposters, no triangles"
                                                : "points representation";
  }
  if (property->GetRenderLinesAsTubes())
  {
    return "lines drawn as tubes: imposters, no triangles";
  }
  if (property->GetRenderPointsAsSpheres() && representation == VTK_SURFACE)
  {
    return "points drawn as spheres: imposters, no triangles";
  }
  // A wireframe of lines draws them as they are (ParaView's outline): nothing is lost.
  return representation == VTK_WIREFRAME && !linesOnly ? "wireframe representation" : nullptr;
}

/// Why a visible prop with bounds is not voxelized (empty: it is): its class, and the reason.
std::string LeftOutReason(vtkProp* prop)
{
  if (auto* slice = vtkImageSlice::SafeDownCast(prop))
  {
    return ImageSliceProxies::LeftOutReason(slice);
  }
  if (auto* volume = vtkVolume::SafeDownCast(prop))
  {
    const std::string why = VolumeVoxels::LeftOutReason(volume);
    return why.empty() ? why : std::string(prop->GetClassName()) + " (" + why + ")";
  }
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!actor)
  {
    return std::string(prop->GetClassName()) + " (not an actor)";
  }
  vtkMapper* mapper = actor->GetMapper();
  // Splats of a shape and molecules are voxelized as their spheres and sticks (ImposterProxies).
  if (ImposterProxies::Splats(actor) || ImposterProxies::Molecule(actor))
  {
    return actor->HasOpaqueGeometry()
      ? std::string()
      : std::string(prop->GetClassName()) + " (translucent, " +
        (ImposterProxies::Molecule(actor) ? "a molecule" : "splats") + ")";
  }
  if (mapper && mapper->IsA("vtkPointGaussianMapper"))
  {
    return std::string(prop->GetClassName()) + " with a " + mapper->GetClassName() +
      " (Gaussian splats without a splat shape, or of scale 0: no surface)";
  }
  // Glyph mappers draw every instance through a polydata helper, dataset mappers (any
  // dataset: unstructured grids, image data) their surface through one: voxelized like polygons.
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper) && !vtkGlyph3DMapper::SafeDownCast(mapper) &&
    !vtkDataSetMapper::SafeDownCast(mapper))
  {
    return std::string(prop->GetClassName()) + " with a " +
      (mapper ? mapper->GetClassName() : "null mapper") + " (not a polydata mapper)";
  }
  // Imposter mappers draw points and lines as shaded spheres and cylinders: no triangles.
  if (mapper->IsA("vtkOpenGLSphereMapper") || mapper->IsA("vtkOpenGLStickMapper"))
  {
    return std::string(prop->GetClassName()) + " with a " + mapper->GetClassName() +
      " (imposter spheres or sticks, no triangles)";
  }
  // Points drawn as spheres are voxelized as spheres (ImposterProxies).
  const char* noArea = ImposterProxies::Applies(actor)
    ? nullptr
    : NoAreaReason(actor->GetProperty(), mapper->GetInputDataObject(0, 0));
  if (noArea)
  {
    return std::string(prop->GetClassName()) + " (" + noArea + ")";
  }
  if (!actor->HasOpaqueGeometry())
  {
    // Its shadows come from its GPU-resident triangles (ShadowTransmittance).
    const std::string unreadable =
      ImposterProxies::Applies(actor) ? "points drawn as spheres" : ComputeUnreadable(actor);
    return unreadable.empty()
      ? unreadable
      : std::string(prop->GetClassName()) + " (translucent, " + unreadable + ")";
  }
  return std::string();
}

/// Whether VTK's culler reads the prop's bounds as they are now, and nothing else of it
/// moves them: plain actors (not followers, which turn with the camera).
bool BoundsFollowSignature(vtkProp* prop)
{
  const char* name = prop->GetClassName();
  return std::strcmp(name, "vtkOpenGLActor") == 0 || std::strcmp(name, "vtkActor") == 0;
}
}

//------------------------------------------------------------------------------
namespace
{
/// Latest modification of an algorithm's inputs: every connection of every port (a glyph
/// mapper's source, an image's pipeline), the data and the algorithm producing it (the first
/// input data's own time into `firstData`, when given).
vtkMTimeType InputsTime(vtkAlgorithm* algorithm, vtkMTimeType* firstData = nullptr)
{
  vtkMTimeType t = 0;
  for (int port = 0; algorithm && port < algorithm->GetNumberOfInputPorts(); ++port)
  {
    for (int c = 0; c < algorithm->GetNumberOfInputConnections(port); ++c)
    {
      // The connection once, its producer's output from there (GetInputDataObject and
      // GetInputAlgorithm would each look the connection up again, in every frame's scan).
      vtkAlgorithmOutput* connection = algorithm->GetInputConnection(port, c);
      vtkAlgorithm* producer = connection ? connection->GetProducer() : nullptr;
      if (!producer)
      {
        continue;
      }
      t = std::max(t, producer->GetMTime());
      if (vtkDataObject* data = producer->GetOutputDataObject(connection->GetIndex()))
      {
        const vtkMTimeType modified = data->GetMTime();
        if (firstData && port == 0 && c == 0)
        {
          *firstData = modified;
        }
        t = std::max(t, modified);
      }
    }
  }
  return t;
}

/// What a mapper draws with beyond its own settings: the planes it clips with (moving a
/// plane does not modify the mapper or its plane collection).
vtkMTimeType ClippingTime(vtkAbstractMapper* mapper)
{
  vtkMTimeType t = 0;
  if (vtkPlaneCollection* planes = mapper->GetClippingPlanes())
  {
    t = planes->GetMTime();
    for (int i = 0; i < planes->GetNumberOfItems(); ++i)
    {
      t = std::max(t, planes->GetItem(i)->GetMTime());
    }
  }
  return t;
}

/// The actor's textures' images and its shader uniforms, which its own time does not cover.
vtkMTimeType MaterialTime(vtkActor* actor)
{
  vtkMTimeType t = 0;
  if (vtkTexture* texture = actor->GetTexture())
  {
    t = std::max(t, InputsTime(texture));
  }
  for (const auto& named : actor->GetProperty()->GetAllTextures())
  {
    t = std::max(t, InputsTime(named.second));
  }
  if (vtkShaderProperty* shaders = actor->GetShaderProperty())
  {
    t = std::max({ t, shaders->GetMTime(), shaders->GetVertexCustomUniforms()->GetMTime(),
      shaders->GetFragmentCustomUniforms()->GetMTime(),
      shaders->GetGeometryCustomUniforms()->GetMTime() });
  }
  return t;
}

/// An assembly's own transform, and of each part (nested assemblies too) what it draws: its
/// mapper, inputs, material, clipping, user matrix and transform, property and texture, but
/// not the part's own time, which the assembly bumps at every render (it pokes its matrix
/// into each part before drawing it). A part moved or hidden on its own inside an assembly
/// is therefore seen only with the next change of its assembly.
vtkMTimeType AssemblyTime(vtkAssembly* assembly)
{
  vtkMTimeType t = assembly->vtkProp3D::GetMTime();
  vtkProp3DCollection* parts = assembly->GetParts();
  vtkCollectionSimpleIterator it;
  parts->InitTraversal(it);
  while (vtkProp3D* part = parts->GetNextProp3D(it))
  {
    if (auto* nested = vtkAssembly::SafeDownCast(part))
    {
      t = std::max(t, AssemblyTime(nested));
      continue;
    }
    if (vtkMatrix4x4* matrix = part->GetUserMatrix())
    {
      t = std::max(t, matrix->GetMTime());
    }
    if (vtkLinearTransform* transform = part->GetUserTransform())
    {
      t = std::max(t, transform->GetMTime());
    }
    auto* actor = vtkActor::SafeDownCast(part);
    if (!actor || !actor->GetMapper())
    {
      continue;
    }
    vtkMapper* mapper = actor->GetMapper();
    t = std::max({ t, MaterialTime(actor), actor->GetProperty()->GetMTime(), mapper->GetMTime(),
      InputsTime(mapper), ClippingTime(mapper) });
    if (vtkTexture* texture = actor->GetTexture())
    {
      t = std::max(t, texture->GetMTime());
    }
  }
  return t;
}
}

vtkMTimeType PropReader::ActorSignature(vtkActor* actor, vtkMTimeType* inputTime)
{
  vtkMapper* mapper = actor->GetMapper();
  vtkMTimeType inputModified = 0;
  const vtkMTimeType inputs = InputsTime(mapper, &inputModified);
  if (inputTime)
  {
    *inputTime = inputModified;
  }
  // Before the actor's own time: asking for its property and shader property creates them
  // when it has none, which modifies the actor.
  const vtkMTimeType material = MaterialTime(actor);
  return std::max({ material, actor->GetMTime(), mapper->GetMTime(), inputs,
    ClippingTime(mapper) });
}

vtkMTimeType PropReader::PropSignature(vtkProp* prop, vtkMTimeType* inputTime)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (actor && actor->GetMapper())
  {
    return ActorSignature(actor, inputTime);
  }
  if (auto* assembly = vtkAssembly::SafeDownCast(prop))
  {
    return AssemblyTime(assembly);
  }
  // Images and volumes: their mapper and its inputs.
  vtkAbstractMapper* mapper = nullptr;
  if (vtkImageSlice* slice = vtkImageSlice::SafeDownCast(prop))
  {
    mapper = slice->GetMapper();
  }
  else if (vtkVolume* volume = vtkVolume::SafeDownCast(prop))
  {
    mapper = volume->GetMapper();
  }
  return mapper ? std::max({ prop->GetMTime(), mapper->GetMTime(), InputsTime(mapper),
                    ClippingTime(mapper) })
                : prop->GetMTime();
}

vtkMTimeType PropReader::DrawnSignature(vtkProp* prop, vtkMTimeType scanned)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (actor && actor->GetMapper())
  {
    return std::max({ scanned, actor->GetMTime(), actor->GetMapper()->GetMTime() });
  }
  return PropSignature(prop);
}

//------------------------------------------------------------------------------
void PropReader::Begin(vtkRenderer* renderer, bool inRender)
{
  this->Next = 0;
  this->Culled = false;
  if (!inRender)
  {
    return;
  }
  vtkCollectionSimpleIterator it;
  renderer->GetCullers()->InitTraversal(it);
  while (vtkCuller* culler = renderer->GetCullers()->GetNextCuller(it))
  {
    this->Culled = this->Culled || vtkFrustumCoverageCuller::SafeDownCast(culler);
  }
}

const PropReading& PropReader::Read(vtkProp* prop)
{
  if (this->Next == this->Readings.size())
  {
    this->Readings.emplace_back();
  }
  PropReading& reading = this->Readings[this->Next++];
  if (this->Culled && prop->GetVisibility() && reading.Prop == prop &&
    BoundsFollowSignature(prop))
  {
    // The culler updated the pipeline: an unchanged signature means unchanged bounds.
    vtkMTimeType inputTime = 0;
    const vtkMTimeType signature = PropSignature(prop, &inputTime);
    if (signature == reading.Signature && inputTime == reading.InputTime)
    {
      return reading;
    }
  }
  reading.Prop = prop;
  ReadAll(prop, reading);
  return reading;
}

void PropReader::ReadAll(vtkProp* prop, PropReading& reading)
{
  // Empty props (e.g. ParaView's selection and axes actors) are neither voxelized nor
  // worth a warning.
  const double* b = prop->GetVisibility() ? prop->GetBounds() : nullptr;
  reading.HasBounds = b && vtkMath::AreBoundsInitialized(b);
  if (reading.HasBounds)
  {
    std::copy(b, b + 6, reading.Bounds);
  }
  reading.LeftOut = reading.HasBounds ? LeftOutReason(prop) : std::string();
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  reading.Translucent =
    reading.HasBounds && reading.LeftOut.empty() && actor && !actor->HasOpaqueGeometry();
  // After what modifies the prop while it is read: the bounds (they update its pipeline),
  // the keys (VTK modifies a prop when it first gets property keys) and whether it is
  // opaque (asking creates a mapper's default lookup table). The signature keys the records
  // and the traced image alike.
  EnsurePropertyKeys(prop);
  reading.Signature = PropSignature(prop, &reading.InputTime);
}

void PropReader::End()
{
  this->Readings.resize(this->Next);
}

}
