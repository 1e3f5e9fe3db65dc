//VTK::System::Dec
// Copies the composited display image (RGBA8, clamped) into VTK's framebuffer, with the
// G-buffer's depth so that the translucent, volume and overlay passes that follow depth-test
// against the scene.
in vec2 texCoord;
uniform sampler2D compositeColor; // the display image
uniform sampler2D gbufferDepth;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = texture(compositeColor, texCoord);
  gl_FragDepth = texture(gbufferDepth, texCoord).r;
}
