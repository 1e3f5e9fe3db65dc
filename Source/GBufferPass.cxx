#include "GBufferPass.h"

#include "Frame.h"
#include "GLHelpers.h"
#include "SceneScan.h"
#include "VoxelGIShaders.h"
#include "StageIds.h"
#include "shader_interface.h"

#include "vtkActor.h"
#include "vtkCameraPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProperty.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <cmath>
#include <vector>

namespace voxelgi
{

namespace
{
/// The render pass VTK's mappers see while they draw into any G-buffer of the thread. A
/// mapper rebuilds its shaders whenever the pass object it draws for changes, so with a pass
/// object per G-buffer, a mapper shown in several viewports would rebuild in each of them
/// every frame. The hooks go to the G-buffer drawing now.
class GBufferShaders : public vtkOpenGLRenderPass
{
public:
  static GBufferShaders* New();
  vtkTypeMacro(GBufferShaders, vtkOpenGLRenderPass);

  static GBufferShaders* Get()
  {
    thread_local vtkSmartPointer<GBufferShaders> shared = vtkSmartPointer<GBufferShaders>::New();
    return shared;
  }
  /// Draw for `gbuffer` into the state's props (PreRender), or stop (PostRender).
  void Begin(GBufferPass* gbuffer, bool litScene, bool fromVTKDraw, const vtkRenderState* s)
  {
    if (litScene != this->LitScene || fromVTKDraw != this->FromVTKDraw)
    {
      this->LitScene = litScene;
      this->FromVTKDraw = fromVTKDraw;
      this->ShaderStageTime.Modified(); // gbuffer.frag depends on both
    }
    this->Drawing = gbuffer;
    this->PreRender(s);
  }
  void End(const vtkRenderState* s)
  {
    this->PostRender(s);
    this->Drawing = nullptr;
  }
  void Render(const vtkRenderState*) override {}
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override
  {
    return this->Drawing->ReplaceShaderValues(
      vertexShader, geometryShader, fragmentShader, mapper, prop);
  }
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject*) override
  {
    return this->Drawing->SetParameters(program, mapper, prop);
  }
  vtkMTimeType GetShaderStageMTime() override { return this->ShaderStageTime.GetMTime(); }

private:
  GBufferPass* Drawing = nullptr;
  bool LitScene = true;
  bool FromVTKDraw = false;
  vtkTimeStamp ShaderStageTime;
};
vtkStandardNewMacro(GBufferShaders);

/// Whether `fragment` discards only where VTK's shader tests its colour's alpha against zero.
bool OnlyDiscardsZeroAlpha(const std::string& fragment)
{
  const std::string test = "gl_FragData[0].a <= 0.0";
  for (std::size_t at = fragment.find("discard"); at != std::string::npos;
       at = fragment.find("discard", at + 1))
  {
    const std::size_t before = at > 64 ? at - 64 : 0;
    if (fragment.substr(before, at - before).find(test) == std::string::npos)
    {
      return false;
    }
  }
  return true;
}
}

vtkStandardNewMacro(GBufferPass);

GBufferPass::GBufferPass()
{
  this->OpaqueSequence->SetPasses(this->OpaquePasses);
  this->OpaqueCamera->SetDelegatePass(this->OpaqueSequence);
}

GBufferPass::~GBufferPass() = default;

//------------------------------------------------------------------------------
bool GBufferPass::Prepare(const Frame& frame, std::string& error)
{
  const int width = frame.Width;
  const int height = frame.Height;
  // VTK's own draw makes the G-buffer where its fragments store in draw order and one of the
  // framebuffer's samples lies near each pixel's centre (NVIDIA's 8x: 0.2 pixels). Patterns
  // without one (4x and 2x: 0.35-0.4 pixels) would lean every surface's edge that far, or, a
  // different sample in neighbouring pixels, dot the edges: there VTK draws twice.
  if (this->InDrawOrder < 0)
  {
    this->InDrawOrder = StoresInDrawOrder() ? 1 : 0;
  }
  const bool fromVTKDraw =
    this->InDrawOrder == 1 && this->FindCentralSample() <= MaxCentralSampleDistance;
  if (this->Depth && fromVTKDraw != this->FromVTKDraw)
  {
    this->ReleaseGraphicsResources(frame.Window);
  }
  if (!this->Depth)
  {
    vtkOpenGLRenderWindow* renWin = frame.Window;
    this->FromVTKDraw = fromVTKDraw;
    // The fewest bytes a pixel (gbuffer.frag, gbuffer_encoding.glsl): with few raster units
    // the G-buffer's time grows with them. VTK's colour keeps its alpha and half floats.
    this->Color = NewImageTexture(renWin, GL_RGBA16F, width, height);
    this->Normal = NewImageTexture(renWin, GL_RGB10_A2, width, height);
    this->Material = NewImageTexture(renWin, GL_RGBA8, width, height);
    this->Ambient = NewImageTexture(renWin, GL_R11F_G11F_B10F, width, height);
    if (this->FromVTKDraw)
    {
      this->Depth = NewImageTexture(renWin, GL_R32F, width, height, 1);
    }
    else
    {
      this->Depth = vtkSmartPointer<vtkTextureObject>::New();
      this->Depth->SetContext(renWin);
      this->Depth->SetMinificationFilter(vtkTextureObject::Nearest);
      this->Depth->SetMagnificationFilter(vtkTextureObject::Nearest);
      this->Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
      this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->Framebuffer->SetContext(renWin);
    }
  }
  this->Color->Resize(width, height);
  this->Normal->Resize(width, height);
  this->Material->Resize(width, height);
  this->Ambient->Resize(width, height);
  this->Depth->Resize(width, height);
  this->LitScene = frame.LitScene;
  return !this->FromVTKDraw ||
    this->Clear.BuildOnce(shaders::gbuffer_clear_comp, "G-buffer clear", error);
}

int CentralSample(const float* positions, int count, float& distance)
{
  // Of the samples nearest the centre (the standard patterns place two or four at the same
  // distance around it), the first: where neighbouring pixels took different ones, an edge
  // between surfaces of different light was dotted (Present gives a pixel's samples the
  // light of its surface).
  int central = 0;
  distance = 1.f;
  for (int i = 0; i < count; ++i)
  {
    const float d = std::hypot(positions[2 * i] - 0.5f, positions[2 * i + 1] - 0.5f);
    if (d < distance - 1e-3f)
    {
      distance = d;
      central = i;
    }
  }
  return central;
}

float GBufferPass::FindCentralSample()
{
  // The positions are asked for again only when the framebuffer's sample count changes.
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (samples == this->Samples)
  {
    return this->CentralDistance;
  }
  this->Samples = samples;
  this->CentralSample = 0;
  this->CentralDistance = 0.f;
  if (samples > 1)
  {
    std::vector<float> positions(2 * static_cast<std::size_t>(samples));
    for (int i = 0; i < samples; ++i)
    {
      glGetMultisamplefv(GL_SAMPLE_POSITION, static_cast<GLuint>(i), &positions[2 * i]);
    }
    this->CentralSample =
      voxelgi::CentralSample(positions.data(), samples, this->CentralDistance);
  }
  return this->CentralDistance;
}

bool GBufferPass::StoresInDrawOrder()
{
  // Mesa's software rasterizers shade each tile's fragments on one thread in draw order.
  const std::string renderer = RendererName();
  return HasExtension("GL_ARB_fragment_shader_interlock") ||
    renderer.find("llvmpipe") != std::string::npos ||
    renderer.find("softpipe") != std::string::npos;
}

//------------------------------------------------------------------------------
void GBufferPass::Run(const Frame& frame)
{
  ScopedStage stage(*frame.Clock, stage::GBuffer);
  this->SelectOpaque(frame);
  if (this->FromVTKDraw)
  {
    this->DrawWithVTK(frame);
  }
  else
  {
    this->Draw(frame, this->Framebuffer);
  }
}

void GBufferPass::DrawWithVTK(const Frame& frame)
{
  BindImage2D(VOXELGI_GBUFFER_DEPTH_UNIT, this->Depth, GL_READ_WRITE, GL_R32F);
  BindImage2D(VOXELGI_GBUFFER_COLOR_UNIT, this->Color, GL_WRITE_ONLY, GL_RGBA16F);
  BindImage2D(VOXELGI_GBUFFER_SURFACE_UNIT, this->Normal, GL_WRITE_ONLY, GL_RGB10_A2);
  BindImage2D(VOXELGI_GBUFFER_MATERIAL_UNIT, this->Material, GL_WRITE_ONLY, GL_RGBA8);
  BindImage2D(VOXELGI_GBUFFER_AMBIENT_UNIT, this->Ambient, GL_WRITE_ONLY, GL_R11F_G11F_B10F);
  // The depth starts at the far plane; the colour at the background, as VTK's clear leaves it
  // where no surface is.
  const double* background = frame.Renderer->GetBackground();
  const float color[4] = { static_cast<float>(background[0]), static_cast<float>(background[1]),
    static_cast<float>(background[2]), static_cast<float>(frame.Renderer->GetBackgroundAlpha()) };
  this->Clear.Use(frame.Window);
  this->Clear.SetVec4("background", color);
  this->Clear.DispatchImage(frame.Width, frame.Height, 8);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  this->Origin[0] = frame.X;
  this->Origin[1] = frame.Y;
  this->Draw(frame, nullptr);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  this->DrawnIn = frame.RenderStarts[0];
  this->Drawn = true;
}

int GBufferPass::RenderVTK(const Frame& frame)
{
  this->SelectOpaque(frame);
  if (!this->FromVTKDraw)
  {
    this->Draw(frame, nullptr);
  }
  // Where VTK's draw stores the G-buffer, Run drew VTK's image already in this render.
  else if (!(this->Drawn && this->DrawnIn == frame.RenderStarts[0]))
  {
    this->DrawWithVTK(frame);
  }
  this->Drawn = false;
  return this->GetNumberOfRenderedProps();
}

void GBufferPass::SelectOpaque(const Frame& frame)
{
  this->Opaque = frame.Delegate;
  if (auto* steps = vtkRenderStepsPass::SafeDownCast(frame.Delegate))
  {
    this->OpaquePasses->RemoveAllItems();
    for (vtkRenderPass* pass : { steps->GetLightsPass(), steps->GetOpaquePass() })
    {
      if (pass)
      {
        this->OpaquePasses->AddItem(pass);
      }
    }
    this->Opaque = this->OpaqueCamera;
  }
}

void GBufferPass::Draw(const Frame& frame, vtkOpenGLFramebufferObject* target)
{
  vtkRenderState state(frame.Renderer);
  state.SetPropArrayAndCount(frame.State->GetPropArray(), frame.State->GetPropArrayCount());
  state.SetFrameBuffer(target ? target : frame.State->GetFrameBuffer());
  this->IntoGBuffer = target != nullptr;
  this->Render(&state);
  this->IntoGBuffer = false;
}

void GBufferPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  GBufferShaders* shaders = GBufferShaders::Get();
  shaders->Begin(this, this->LitScene, this->FromVTKDraw, s);
  if (this->IntoGBuffer)
  {
    this->Begin();
  }
  if (this->Opaque)
  {
    this->Opaque->Render(s);
    this->NumberOfRenderedProps += this->Opaque->GetNumberOfRenderedProps();
  }
  if (this->IntoGBuffer)
  {
    this->End();
  }
  shaders->End(s);
}

void GBufferPass::Begin()
{
  vtkOpenGLFramebufferObject* target = this->Framebuffer;
  target->SaveCurrentBindingsAndBuffers();
  target->Bind();
  target->AddColorAttachment(0, this->Color);
  target->AddColorAttachment(1, this->Normal);
  target->AddColorAttachment(2, this->Material);
  target->AddColorAttachment(3, this->Ambient);
  target->AddDepthAttachment(this->Depth);
  // VTK's clear reaches every attachment (one clear is far cheaper than clearing the data
  // attachments apart); the composite tells the background by its depth.
  target->ActivateDrawBuffers(4);
  target->StartNonOrtho(this->Color->GetWidth(), this->Color->GetHeight());
  for (unsigned int i = 0; i < 3; ++i)
  {
    this->BlendWasEnabled[i] = glIsEnabledi(GL_BLEND, i + 1) == GL_TRUE;
  }
  SetDataBlending(true);
}

void GBufferPass::SetDataBlending(bool polyData)
{
  // VTK blends its opaque pass; the data attachments must be written as they are. Other
  // mappers' shaders write no surface: blending makes it zero (kind 0, no GI terms), whatever
  // their second output holds.
  glDisablei(GL_BLEND, 2);
  glDisablei(GL_BLEND, 3);
  if (polyData)
  {
    glDisablei(GL_BLEND, 1);
  }
  else
  {
    glEnablei(GL_BLEND, 1);
    glBlendFunci(1, GL_ZERO, GL_ZERO);
  }
}

void GBufferPass::End()
{
  for (unsigned int i = 0; i < 3; ++i)
  {
    if (this->BlendWasEnabled[i])
    {
      glEnablei(GL_BLEND, i + 1);
    }
    else
    {
      glDisablei(GL_BLEND, i + 1);
    }
  }
  // Draw buffer 1's blend function back to the one VTK's state holds for all buffers.
  int blend[4];
  static_cast<vtkOpenGLRenderWindow*>(this->Framebuffer->GetContext())
    ->GetState()
    ->GetBlendFuncState(blend);
  glBlendFuncSeparatei(1, blend[0], blend[1], blend[2], blend[3]);
  this->Framebuffer->UnBind();
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
}


//------------------------------------------------------------------------------
bool GBufferPass::ReplaceShaderValues(
  std::string&, std::string&, std::string& fragment, vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    return true;
  }
  std::string defines;
  if (fragment.find("normalVCVSOutput") != std::string::npos)
  {
    defines += "#define VOXELGI_HAS_NORMAL\n";
  }
  if (fragment.find("vec4 tcolor =") != std::string::npos)
  {
    defines += "#define VOXELGI_HAS_TEXTURE\n";
  }
  if (fragment.find("float specularPower =") != std::string::npos)
  {
    defines += "#define VOXELGI_HAS_SPECULAR\n";
  }
  if (fragment.find("vec3 ambientColor") != std::string::npos)
  {
    defines += "#define VOXELGI_HAS_AMBIENT\n";
  }
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (this->FromVTKDraw)
  {
    // Extensions before any declaration, VTK's included.
    defines = std::string("#extension GL_ARB_shader_image_load_store : require\n"
                          "#extension GL_ARB_shading_language_420pack : require\n"
                          "#extension GL_ARB_gpu_shader5 : require\n"
                          "#ifdef GL_ARB_fragment_shader_interlock\n"
                          "#extension GL_ARB_fragment_shader_interlock : enable\n"
                          "#endif\n"
                          "#define VOXELGI_GBUFFER_IMAGES\n") +
      defines + shaders::gbuffer_images_glsl;
    // Sprites (spheres, tubes) set their depth: the G-buffer takes that one.
    const bool setsDepth = fragment.find("gl_FragDepth =") != std::string::npos;
    if (setsDepth)
    {
      defines += "#define VOXELGI_SETS_DEPTH\n";
    }
    // Fragments a nearer surface hides run no shader (with the stores, the GPU would run them
    // all), unless the shader sets its depth or may discard a fragment of VTK's opaque pass
    // (splats; the test of zero alpha discards nothing there, unless the actor is forced
    // opaque), which must then not have written its depth.
    if (!setsDepth && !(actor && actor->GetForceOpaque()) && OnlyDiscardsZeroAlpha(fragment))
    {
      defines += "layout(early_fragment_tests) in;\n";
    }
  }
  defines += "uniform float voxelgiOccludable;\n";
  if (!this->LitScene && actor && actor->GetProperty()->GetLighting())
  {
    defines += "#define VOXELGI_AMBIENT_ONLY\n";
  }
  vtkShaderProgram::Substitute(fragment, "//VTK::System::Dec",
    "//VTK::System::Dec\n" + defines + shaders::gbuffer_encoding_glsl);
  const std::size_t end = fragment.rfind('}');
  if (end != std::string::npos)
  {
    fragment.insert(end, shaders::gbuffer_frag);
  }
  return true;
}

bool GBufferPass::SetParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop)
{
  // Polydata mappers write all attachments, other mappers the colour and (SetDataBlending)
  // an empty surface. VTK's own framebuffer keeps its draw buffers: the data outputs go
  // nowhere there (where its draw stores the G-buffer, they are images).
  const bool polyData = vtkOpenGLPolyDataMapper::SafeDownCast(mapper) != nullptr;
  if (this->IntoGBuffer)
  {
    this->Framebuffer->ActivateDrawBuffers(polyData ? 4 : 2);
  }
  if (polyData)
  {
    // An emitter's ambient colour is its emission, which nothing occludes. A surface VTK
    // does not light (no diffuse or specular term, or lighting off: an image slice's quad,
    // a flat-coloured actor) shows its colour as VTK does.
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    vtkProperty* property = actor ? actor->GetProperty() : nullptr;
    const bool unlit = property &&
      (!property->GetLighting() || (property->GetDiffuse() == 0.0 && property->GetSpecular() == 0.0));
    program->SetUniformf("voxelgiOccludable", unlit || Emits(PropEmission(prop)) ? 0.0f : 1.0f);
    if (this->FromVTKDraw)
    {
      program->SetUniform2i("voxelgiOrigin", this->Origin);
      program->SetUniformi("voxelgiCentralSample", this->CentralSample);
    }
  }
  // Before every draw: VTK's state handling may have re-enabled blending for all buffers.
  if (this->IntoGBuffer)
  {
    SetDataBlending(polyData);
  }
  return true;
}

//------------------------------------------------------------------------------
void GBufferPass::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkTextureObject* texture : { this->Color.Get(), this->Normal.Get(), this->Material.Get(),
         this->Ambient.Get(), this->Depth.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Framebuffer = nullptr;
  this->Clear.Release();
  this->Samples = -1; // another window's framebuffer may place its samples elsewhere
  this->Color = this->Normal = this->Material = this->Ambient = this->Depth = nullptr;
}

}
