#include "PresentSamples.h"

#include "Frame.h"
#include "VoxelGIShaders.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace voxelgi
{

namespace
{
/// The image format qualifier of a colour texture's internal format; null where an image
/// cannot hold it (sRGB, packed formats).
const char* ImageFormat(int internalFormat)
{
  switch (internalFormat)
  {
    case GL_RGBA8:
      return "rgba8";
    case GL_RGBA16F:
      return "rgba16f";
    case GL_RGBA32F:
      return "rgba32f";
    default:
      return nullptr;
  }
}
}

bool PresentSamples::Run(
  const Frame& frame, vtkTextureObject* scale, vtkTextureObject* add, vtkTextureObject* depth)
{
  int framebuffer = 0, buffer = 0, color[5] = {}, vtkDepth[5] = {};
  unsigned int types[2];
  if (!DescribeDrawTarget(framebuffer, buffer, color, vtkDepth, types) ||
    types[0] != GL_TEXTURE || types[1] != GL_TEXTURE || color[2] != vtkDepth[2] ||
    !ImageFormat(color[1]) || frame.X + frame.Width > color[3] ||
    frame.Y + frame.Height > color[4])
  {
    return false;
  }
  const int samples = color[2];
  GLint imageSamples = 0;
  glGetIntegerv(GL_MAX_IMAGE_SAMPLES, &imageSamples);
  if (samples > imageSamples)
  {
    return false;
  }
  std::string defines = std::string("#define VOXELGI_COLOR_FORMAT ") + ImageFormat(color[1]) +
    "\n" + (samples > 0 ? "#define VOXELGI_MULTISAMPLE\n" : "");
  std::string error;
  if (defines == this->Refused ||
    !this->Program.BuildOnce(shaders::present_samples_comp, "present samples", error, defines))
  {
    this->Refused = defines;
    return false;
  }
  GLProgram& p = this->Program;
  p.Use(frame.Window);
  ScopedTextures inputs({ scale, add, depth });
  SamplerBindings framebufferDepth(frame.Window);
  const int depthUnit = framebufferDepth.AddTexture(static_cast<unsigned int>(vtkDepth[0]),
    samples > 0 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D);
  if (!inputs.Complete() || !framebufferDepth.Complete())
  {
    glUseProgram(0);
    return false;
  }
  p.SetInt("presentScale", scale->GetTextureUnit());
  p.SetInt("presentAdd", add->GetTextureUnit());
  p.SetInt("gbufferDepth", depth->GetTextureUnit());
  p.SetInt("framebufferDepth", depthUnit);
  p.SetInt("samples", samples > 0 ? samples : 1);
  p.SetIVec2("viewportOrigin", frame.X, frame.Y);
  glBindImageTexture(0, static_cast<GLuint>(color[0]), 0, GL_FALSE, 0, GL_READ_WRITE,
    static_cast<GLenum>(color[1]));
  p.DispatchImage(frame.Width, frame.Height, 8);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
  // VTK's next steps draw, blit and resolve what the dispatch wrote.
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  return true;
}

void PresentSamples::ReleaseGraphicsResources()
{
  this->Program.Release();
  this->Refused.clear();
}

}
