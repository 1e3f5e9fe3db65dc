// G-buffer outputs, appended to the end of main() of VTK's polydata fragment shader by
// vtkVoxelGIPass (gbuffer_encoding.glsl goes with VTK's declarations). The G-buffer holds
// VTK's shaded colour, the surface (normal, specular power and kind, packed), the albedo
// (diffuse colour times texture) and specular intensity, and the ambient term (times texture)
// that the composite builds on. Two ways (GBufferPass):
// - VOXELGI_GBUFFER_IMAGES: VTK's own draw of its image, at the window's multisampling,
//   stores them at one sample per pixel into images, with the depth of the pixel's centre: of
//   the fragments covering the pixel's sample nearest its centre the nearest wins, in the
//   order VTK draws (a fragment-shader interlock, or a rasterizer that shades each pixel in
//   draw order). No second draw of the scene.
// - otherwise a draw of its own into a framebuffer of one sample: attachment 0 keeps VTK's
//   colour, 1 the surface, 2 the material, 3 the ambient term (VTK's framebuffer has only
//   attachment 0: the rest is dropped there).
// The kind says what a pixel means: 0 nothing a polydata mapper drew (the G-buffer writes
// other mappers' surface as zero, and tells its background by the depth), 1 VTK's colour is
// kept and the ambient term is its part AO darkens (zero on emitters, voxelgiOccludable 0), 2
// and 3 only the ambient term is kept, of a lit surface in a renderer without lights (GI
// replaces its flat colour by ambient + indirect), darkened by AO (2) or not, an emitter's
// (3). The pass defines VOXELGI_HAS_NORMAL, VOXELGI_HAS_TEXTURE, VOXELGI_HAS_SPECULAR and
// VOXELGI_HAS_AMBIENT after what VTK's shader computes, and VOXELGI_AMBIENT_ONLY for lit
// surfaces in a renderer without lights.
#ifdef VOXELGI_HAS_TEXTURE
  vec3 voxelgiTexture = tcolor.rgb;
#else
  vec3 voxelgiTexture = vec3(1.0);
#endif
#ifdef VOXELGI_HAS_SPECULAR
  float voxelgiSpecularPower = specularPower;
  float voxelgiSpecular = max(specularColor.r, max(specularColor.g, specularColor.b));
#else
  float voxelgiSpecularPower = 1.0;
  float voxelgiSpecular = 0.0;
#endif
#ifdef VOXELGI_HAS_NORMAL
  vec3 voxelgiNormal = normalVCVSOutput;
#else
  vec3 voxelgiNormal = vec3(0.0);
#endif
#if defined(VOXELGI_AMBIENT_ONLY) && defined(VOXELGI_HAS_AMBIENT)
  float voxelgiKind = voxelgiOccludable > 0.0 ? 2.0 : 3.0;
  vec3 voxelgiAmbient = ambientColor * voxelgiTexture;
#elif defined(VOXELGI_HAS_AMBIENT)
  float voxelgiKind = 1.0;
  vec3 voxelgiAmbient = voxelgiOccludable * ambientColor * voxelgiTexture;
#else
  float voxelgiKind = 1.0;
  vec3 voxelgiAmbient = vec3(0.0);
#endif
#ifdef VOXELGI_GBUFFER_IMAGES
  {
    ivec2 voxelgiPixel = ivec2(gl_FragCoord.xy) - voxelgiOrigin;
#ifdef GL_ARB_fragment_shader_interlock
    beginInvocationInterlockARB();
#endif
    // The fragment that covers the pixel's sample nearest its centre, as a draw at one
    // sample per pixel takes the one covering the centre. The same sample in every pixel:
    // where pixels took different ones, an edge between surfaces of different light was
    // dotted (Present gives a pixel's samples the light of its surface).
    int voxelgiSample = voxelgiCentralSample;
#ifdef VOXELGI_SETS_DEPTH
    float voxelgiDepth = gl_FragDepth;
#else
    float voxelgiDepth = gl_FragCoord.z;
#endif
    if ((gl_SampleMaskIn[0] & (1 << voxelgiSample)) != 0 &&
      voxelgiDepth <= imageLoad(gbufferDepthImage, voxelgiPixel).r)
    {
      imageStore(gbufferDepthImage, voxelgiPixel, vec4(voxelgiDepth));
      imageStore(gbufferColorImage, voxelgiPixel, gl_FragData[0]);
      imageStore(gbufferSurfaceImage, voxelgiPixel,
        gbufferEncodeSurface(voxelgiNormal, voxelgiSpecularPower, voxelgiKind));
      imageStore(gbufferMaterialImage, voxelgiPixel,
        vec4(diffuseColor * voxelgiTexture, voxelgiSpecular));
      imageStore(gbufferAmbientImage, voxelgiPixel, vec4(voxelgiAmbient, 1.0));
    }
#ifdef GL_ARB_fragment_shader_interlock
    endInvocationInterlockARB();
#endif
  }
#else
  gl_FragData[1] = gbufferEncodeSurface(voxelgiNormal, voxelgiSpecularPower, voxelgiKind);
  gl_FragData[2] = vec4(diffuseColor * voxelgiTexture, voxelgiSpecular);
  gl_FragData[3] = vec4(voxelgiAmbient, 1.0);
#endif
