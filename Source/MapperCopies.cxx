#include "MapperCopies.h"

#include "SceneScan.h"

#include "vtkActor.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkGlyph3DMapper.h"
#include "vtkInformation.h"
#include "vtkMapper.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

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
vtkMapper* MapperCopies::CopyOf(vtkActor* actor)
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
  return copy.Mapper;
}

//------------------------------------------------------------------------------
int MapperCopies::Draw(vtkActor* actor, vtkRenderer* renderer)
{
  if (!actor || !actor->GetMapper())
  {
    return 0;
  }
  vtkMapper* mapper = this->CopyOf(actor);
  // What vtkActor::RenderOpaqueGeometry does, with the copy in place of the actor's mapper:
  // the property and the textures are the actor's own.
  vtkProperty* property = actor->GetProperty();
  property->Render(actor, renderer);
  if (vtkProperty* backface = actor->GetBackfaceProperty())
  {
    backface->BackfaceRender(actor, renderer);
  }
  vtkTexture* texture = actor->GetTexture();
  if (texture)
  {
    texture->Render(renderer);
  }
  actor->Render(renderer, mapper);
  property->PostRender(actor, renderer);
  if (texture)
  {
    texture->PostRender(renderer);
  }
  return 1;
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
      if (it->second.Mapper)
      {
        it->second.Mapper->ReleaseGraphicsResources(window);
      }
      it = this->Copies.erase(it);
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
}

}
