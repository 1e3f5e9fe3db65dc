// G-buffer outputs, appended to the end of main() of VTK's polydata fragment shader by
// vtkVoxelGIPass (gbuffer_encoding.glsl goes with VTK's declarations). The same shader draws
// VTK's own image into the window (where only attachment 0 exists, so the rest is dropped) and
// the G-buffer: attachment 0 keeps VTK's shaded colour, 1 the surface (normal, specular power
// and kind, packed), 2 the albedo (diffuse colour times texture) and specular intensity, 3 the
// ambient term (times texture) that the composite builds on. The kind says what it means: 0
// nothing a polydata mapper drew (the G-buffer writes other mappers' surface as zero, and tells
// its background by the depth), 1 VTK's colour is kept and the ambient term is its part AO
// darkens (zero on emitters, voxelgiOccludable 0), 2 and 3 only the ambient term is kept, of a
// lit surface in a renderer without lights (GI replaces its flat colour by ambient + indirect),
// darkened by AO (2) or not, an emitter's (3). The pass defines VOXELGI_HAS_NORMAL,
// VOXELGI_HAS_TEXTURE, VOXELGI_HAS_SPECULAR and VOXELGI_HAS_AMBIENT after what VTK's shader
// computes, and VOXELGI_AMBIENT_ONLY for lit surfaces in a renderer without lights.
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
  gl_FragData[1] = gbufferEncodeSurface(voxelgiNormal, voxelgiSpecularPower, voxelgiKind);
  gl_FragData[2] = vec4(diffuseColor * voxelgiTexture, voxelgiSpecular);
  gl_FragData[3] = vec4(voxelgiAmbient, 1.0);
