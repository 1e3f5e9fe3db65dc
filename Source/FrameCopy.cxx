#include "FrameCopy.h"

#include "Frame.h"
#include "GLHelpers.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderbuffer.h"
#include "vtk_glew.h"

#include <algorithm>

namespace voxelgi
{

FrameCopy::FrameCopy() = default;
FrameCopy::~FrameCopy() = default;

bool FrameCopy::Target::operator==(const Target& other) const
{
  return this->Framebuffer == other.Framebuffer && this->Buffer == other.Buffer &&
    std::equal(this->Color, this->Color + 5, other.Color) &&
    std::equal(this->Depth, this->Depth + 5, other.Depth) &&
    std::equal(this->Viewport, this->Viewport + 4, other.Viewport);
}

bool FrameCopy::Describe(const Frame& frame, Target& target)
{
  unsigned int types[2];
  if (!DescribeDrawTarget(target.Framebuffer, target.Buffer, target.Color, target.Depth, types))
  {
    return false;
  }
  target.Viewport[0] = frame.X;
  target.Viewport[1] = frame.Y;
  target.Viewport[2] = frame.Width;
  target.Viewport[3] = frame.Height;
  return types[0] != GL_NONE && types[1] != GL_NONE && target.Color[2] == target.Depth[2] &&
    target.Color[3] == target.Depth[3] && target.Color[4] == target.Depth[4];
}

void FrameCopy::Store(const Frame& frame)
{
  Target target;
  this->Held = false;
  if (!Describe(frame, target))
  {
    return;
  }
  const bool same = this->Copy && target.Color[1] == this->Source.Color[1] &&
    target.Depth[1] == this->Source.Depth[1] &&
    std::equal(target.Color + 2, target.Color + 5, this->Source.Color + 2);
  if (!same)
  {
    this->ReleaseGraphicsResources(frame.Window);
    const auto w = static_cast<unsigned int>(target.Color[3]);
    const auto h = static_cast<unsigned int>(target.Color[4]);
    const auto samples = static_cast<unsigned int>(target.Color[2]);
    this->Color = vtkSmartPointer<vtkRenderbuffer>::New();
    this->Color->SetContext(frame.Window);
    this->Depth = vtkSmartPointer<vtkRenderbuffer>::New();
    this->Depth->SetContext(frame.Window);
    if (!this->Color->Create(target.Color[1], w, h, samples) ||
      !this->Depth->Create(target.Depth[1], w, h, samples))
    {
      this->ReleaseGraphicsResources(frame.Window);
      return;
    }
    this->Copy = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Copy->SetContext(frame.Window);
    vtkOpenGLState* state = frame.Window->GetState();
    state->PushFramebufferBindings();
    this->Copy->Bind();
    this->Copy->AddColorAttachment(0, this->Color);
    this->Copy->AddDepthAttachment(this->Depth);
    this->Copy->ActivateBuffer(0);
    state->PopFramebufferBindings();
  }
  this->Source = target;
  this->Blit(frame, true);
  this->Held = true;
}

bool FrameCopy::Holds(const Frame& frame) const
{
  Target target;
  return this->Held && Describe(frame, target) && target == this->Source;
}

void FrameCopy::Restore(const Frame& frame)
{
  this->Blit(frame, false);
}

void FrameCopy::Blit(const Frame& frame, bool store)
{
  vtkOpenGLState* state = frame.Window->GetState();
  // Blits are scissored; the rectangle is the viewport already.
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->PushFramebufferBindings();
  const unsigned int copy = this->Copy->GetFBOIndex();
  const auto framebuffer = static_cast<unsigned int>(this->Source.Framebuffer);
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, store ? framebuffer : copy);
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, store ? copy : framebuffer);
  state->vtkglReadBuffer(store ? this->Source.Buffer : GL_COLOR_ATTACHMENT0);
  // Multisampled blits need the same rectangle on both sides: the copy is as large as the
  // framebuffer.
  const int* v = this->Source.Viewport;
  glBlitFramebuffer(v[0], v[1], v[0] + v[2], v[1] + v[3], v[0], v[1], v[0] + v[2], v[1] + v[3],
    GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  state->PopFramebufferBindings();
}

void FrameCopy::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Copy)
  {
    this->Copy->ReleaseGraphicsResources(window);
  }
  for (vtkRenderbuffer* buffer : { this->Color.Get(), this->Depth.Get() })
  {
    if (buffer)
    {
      buffer->ReleaseGraphicsResources(window);
    }
  }
  this->Copy = nullptr;
  this->Color = this->Depth = nullptr;
  this->Held = false;
}

}
