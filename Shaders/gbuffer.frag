// G-buffer outputs, appended to the end of main() of VTK's polydata fragment shader by
// vtkVoxelGIPass while VTK renders the opaque geometry: attachment 0 keeps VTK's own shaded
// colour, 1 gets the view-space normal and specular power, 2 the albedo (diffuse colour
// times texture) and specular intensity, 3 the part of the colour that is VTK's ambient term
// (zero on emitters, voxelgiOccludable 0) and alpha 1 where a polydata mapper drew (VTK's
// clear leaves the background there, alpha 0 by default): the only part AO darkens. The pass defines
// VOXELGI_HAS_NORMAL, VOXELGI_HAS_TEXTURE, VOXELGI_HAS_SPECULAR and VOXELGI_HAS_AMBIENT after
// what VTK's shader computes, and VOXELGI_AMBIENT_ONLY for lit surfaces in a renderer without
// lights, whose flat colour GI replaces by ambient + indirect.
#ifdef VOXELGI_HAS_TEXTURE
  vec3 voxelgiTexture = tcolor.rgb;
#else
  vec3 voxelgiTexture = vec3(1.0);
#endif
#ifdef VOXELGI_AMBIENT_ONLY
  gl_FragData[0].rgb = ambientColor * voxelgiTexture;
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
#ifdef VOXELGI_HAS_AMBIENT
  gl_FragData[3] = vec4(voxelgiOccludable * ambientColor * voxelgiTexture, 1.0);
#else
  gl_FragData[3] = vec4(0.0, 0.0, 0.0, 1.0);
#endif
