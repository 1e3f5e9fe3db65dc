//VTK::System::Dec
// Copies the composited float image into VTK's framebuffer, with the G-buffer's depth so that
// the translucent, volume and overlay passes that follow depth-test against the scene.
in vec2 texCoord;
uniform sampler2D compositeColor;
uniform sampler2D gbufferDepth;
//VTK::Output::Dec
void main()
{
  vec4 c = texture(compositeColor, texCoord);
  gl_FragData[0] = vec4(clamp(c.rgb, 0.0, 1.0), c.a);
  gl_FragDepth = texture(gbufferDepth, texCoord).r;
}
