#include "MapperCopies.h"

#include "SceneScan.h"

#include "vtkActor.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataSetMapper.h"
#include "vtkGlyph3DMapper.h"
#include "vtkInformation.h"
#include "vtkMapper.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <iterator>
#include <unordered_set>

namespace voxelgi
{

namespace
{
// vtkGlyph3DMapper has no ShallowCopy of its own: the colouring settings come from vtkMapper's,
// the rest (points, glyph sources, arrays, scaling and orientation) is copied here.
void CopyGlyphMapper(vtkGlyph3DMapper* source, vtkGlyph3DMapper* copy)
{
  copy->vtkMapper::ShallowCopy(source);
  copy->SetInputConnection(0, source->GetInputConnection(0, 0));
  copy->RemoveAllInputConnections(1);
  for (int i = 0; i < source->GetNumberOfInputConnections(1); ++i)
  {
    copy->AddInputConnection(1, source->GetInputConnection(1, i));
  }
  for (int i = 0; i < 5; ++i) // scale, source index, mask, orientation, selection id arrays
  {
    if (vtkInformation* array = source->GetInputArrayInformation(i))
    {
      copy->GetInputArrayInformation(i)->Copy(array);
    }
  }
  copy->SetScaling(source->GetScaling());
  copy->SetScaleMode(source->GetScaleMode());
  copy->SetScaleFactor(source->GetScaleFactor());
  copy->SetRange(source->GetRange());
  copy->SetOrient(source->GetOrient());
  copy->SetOrientationMode(source->GetOrientationMode());
  copy->SetClamping(source->GetClamping());
  copy->SetSourceIndexing(source->GetSourceIndexing());
  copy->SetUseSourceTableTree(source->GetUseSourceTableTree());
  copy->SetMasking(source->GetMasking());
  copy->SetBlockAttributes(source->GetBlockAttributes());
  copy->SetCullingAndLOD(false); // every instance, whatever the camera
}
}

MapperCopies::~MapperCopies() = default;

//------------------------------------------------------------------------------
MapperCopies::Copy& MapperCopies::CopyOf(vtkActor* actor)
{
  vtkMapper* source = actor->GetMapper();
  Copy& copy = this->Copies[actor];
  if (copy.Actor != actor || copy.Source != source || !copy.Mapper)
  {
    copy.Actor = actor;
    copy.Source = source;
    copy.Mapper.TakeReference(source->NewInstance());
    copy.Synced = 0;
  }
  // The source's time covers its input connection, colouring settings and lookup table.
  const vtkMTimeType sourceTime = source->GetMTime();
  if (sourceTime > copy.Synced)
  {
    vtkMapper* mapper = copy.Mapper;
    // Input connection, scalar colouring (mode, range, array, lookup table, interpolation
    // before mapping), clipping planes, coincident topology, pieces.
    // (vtkOpenGLPolyDataMapper's own ShallowCopy adds only the selection id arrays and the
    // deprecated shader code, which warns; the actor's shader property still applies.)
    auto* glSource = vtkOpenGLPolyDataMapper::SafeDownCast(source);
    auto* glCopy = vtkOpenGLPolyDataMapper::SafeDownCast(mapper);
    auto* glyphSource = vtkGlyph3DMapper::SafeDownCast(source);
    auto* glyphCopy = vtkGlyph3DMapper::SafeDownCast(mapper);
    if (glyphSource && glyphCopy)
    {
      CopyGlyphMapper(glyphSource, glyphCopy);
    }
    else if (glSource && glCopy)
    {
      glCopy->vtkPolyDataMapper::ShallowCopy(glSource);
      // Same shift and scale: the 1e8-offset cases stay exact, and the points VBO is shared.
      glCopy->SetVBOShiftScaleMethod(glSource->GetVBOShiftScaleMethod());
    }
    else
    {
      mapper->ShallowCopy(source);
      // vtkDataSetMapper's ShallowCopy keeps its own input.
      if (vtkDataSetMapper::SafeDownCast(source))
      {
        mapper->SetInputConnection(source->GetInputConnection(0, 0));
      }
    }
    mapper->SetStatic(source->GetStatic());
    auto* compositeSource = vtkCompositePolyDataMapper2::SafeDownCast(source);
    auto* compositeCopy = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
    if (compositeSource && compositeCopy)
    {
      // Block visibility, colours and opacities.
      compositeCopy->SetCompositeDataDisplayAttributes(
        compositeSource->GetCompositeDataDisplayAttributes());
      compositeCopy->SetColorMissingArraysWithNanColor(
        compositeSource->GetColorMissingArraysWithNanColor());
    }
    copy.Synced = source->GetMTime();
  }
  return copy;
}

//------------------------------------------------------------------------------
int MapperCopies::Draw(vtkActor* actor, vtkRenderer* renderer)
{
  if (!actor || !actor->GetMapper())
  {
    return 0;
  }
  Copy& copy = this->CopyOf(actor);
  vtkMapper* mapper = copy.Mapper;
  vtkActor* drawing = this->Drawing(copy, actor);
  // What vtkActor::RenderOpaqueGeometry does, with the copy in place of the actor's mapper:
  // the property and the textures are the actor's own.
  vtkProperty* property = drawing->GetProperty();
  property->Render(drawing, renderer);
  if (vtkProperty* backface = drawing->GetBackfaceProperty())
  {
    backface->BackfaceRender(drawing, renderer);
  }
  vtkTexture* texture = drawing->GetTexture();
  if (texture)
  {
    texture->Render(renderer);
  }
  drawing->Render(renderer, mapper);
  property->PostRender(drawing, renderer);
  if (texture)
  {
    texture->PostRender(renderer);
  }
  return 1;
}

vtkActor* MapperCopies::Drawing(Copy& copy, vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  // What only the displayed image shows: edges and vertices drawn over a surface, lines as
  // tubes, points as spheres.
  const bool overlays = property->GetEdgeVisibility() || property->GetVertexVisibility() ||
    property->GetRenderLinesAsTubes() || property->GetRenderPointsAsSpheres();
  if (actor->IsA("vtkOpenGLActor") && !overlays)
  {
    return actor;
  }
  if (!copy.StandIn)
  {
    copy.StandIn = vtkSmartPointer<vtkActor>::New(); // VTK's factory: an OpenGL actor
    this->StandIns[copy.StandIn] = actor;
  }
  vtkActor* standIn = copy.StandIn;
  // The same objects each frame: nothing is modified unless the actor's are.
  standIn->SetUserMatrix(actor->GetMatrix());
  standIn->SetBackfaceProperty(actor->GetBackfaceProperty());
  standIn->SetTexture(actor->GetTexture());
  standIn->SetPropertyKeys(actor->GetPropertyKeys()); // the stage's render-pass keys
  if (!overlays)
  {
    standIn->SetProperty(property);
    return standIn;
  }
  // These stages draw the surfaces: the voxels take a surface's own colour (VTK's edge code
  // mixes in the edge colour), lines and points add no voxels or shadows as tubes or spheres,
  // and VTK's code for those does not build with these stages' shaders (VTK 9.1's unlit tube
  // edges do not compile at all). A copy of the property draws the surface alone.
  if (!copy.Property || property->GetMTime() > copy.PropertySynced)
  {
    if (!copy.Property)
    {
      copy.Property = vtkSmartPointer<vtkProperty>::New();
    }
    copy.Property->DeepCopy(property);
    copy.Property->SetEdgeVisibility(false);
    copy.Property->SetVertexVisibility(false);
    copy.Property->SetRenderLinesAsTubes(false);
    copy.Property->SetRenderPointsAsSpheres(false);
    copy.PropertySynced = property->GetMTime();
  }
  standIn->SetProperty(copy.Property);
  return standIn;
}

vtkProp* MapperCopies::Original(vtkProp* drawn) const
{
  const auto found = this->StandIns.find(drawn);
  return found != this->StandIns.end() ? found->second : drawn;
}

void MapperCopies::Erase(std::unordered_map<vtkActor*, Copy>::iterator it, vtkWindow* window)
{
  if (it->second.Mapper)
  {
    it->second.Mapper->ReleaseGraphicsResources(window);
  }
  if (it->second.StandIn)
  {
    this->StandIns.erase(it->second.StandIn);
  }
  this->Copies.erase(it);
}

//------------------------------------------------------------------------------
void MapperCopies::Retain(const std::vector<ActorRecord>& records, vtkWindow* window)
{
  std::unordered_set<vtkActor*> kept;
  for (const ActorRecord& record : records)
  {
    kept.insert(record.Actor);
  }
  for (auto it = this->Copies.begin(); it != this->Copies.end();)
  {
    if (!it->second.Actor || !kept.count(it->first))
    {
      auto next = std::next(it);
      this->Erase(it, window);
      it = next;
    }
    else
    {
      ++it;
    }
  }
}

void MapperCopies::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& entry : this->Copies)
  {
    if (entry.second.Mapper)
    {
      entry.second.Mapper->ReleaseGraphicsResources(window);
    }
  }
  this->Copies.clear();
  this->StandIns.clear();
}

}
