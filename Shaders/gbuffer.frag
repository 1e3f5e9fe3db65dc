// G-buffer outputs, appended to the end of main() of VTK's polydata fragment shader by
// vtkVoxelGIPass. The same shader draws VTK's own image into the window (where only
// attachment 0 exists, so the rest is dropped) and the G-buffer: attachment 0 keeps VTK's
// shaded colour, 1 gets the view-space normal and specular power, 2 the albedo (diffuse
// colour times texture) and specular intensity, 3 what the composite builds on: rgb the
// ambient term (times texture) and alpha what it means: 0 nothing a polydata mapper drew
// (VTK's clear leaves alpha 0), 1 VTK's colour is kept and rgb is its part AO darkens (zero
// on emitters, voxelgiOccludable 0), 2 and 3 only rgb is kept, of a lit surface in a
// renderer without lights (GI replaces its flat colour by ambient + indirect), darkened by AO
// (2) or not, an emitter's (3). The pass defines VOXELGI_HAS_NORMAL, VOXELGI_HAS_TEXTURE,
// VOXELGI_HAS_SPECULAR and VOXELGI_HAS_AMBIENT after what VTK's shader computes, and
// VOXELGI_AMBIENT_ONLY for lit surfaces in a renderer without lights.
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
  gl_FragData[1] = vec4(normalVCVSOutput, voxelgiSpecularPower);
#else
  gl_FragData[1] = vec4(0.0, 0.0, 0.0, voxelgiSpecularPower);
#endif
  gl_FragData[2] = vec4(diffuseColor * voxelgiTexture, voxelgiSpecular);
#if defined(VOXELGI_AMBIENT_ONLY) && defined(VOXELGI_HAS_AMBIENT)
  gl_FragData[3] = vec4(ambientColor * voxelgiTexture, voxelgiOccludable > 0.0 ? 2.0 : 3.0);
#elif defined(VOXELGI_HAS_AMBIENT)
  gl_FragData[3] = vec4(voxelgiOccludable * ambientColor * voxelgiTexture, 1.0);
#else
  gl_FragData[3] = vec4(0.0, 0.0, 0.0, 1.0);
#endif
