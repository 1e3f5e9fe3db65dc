// The G-buffer's images, where VTK's own draw stores it (gbuffer.frag with
// VOXELGI_GBUFFER_IMAGES; GBufferPass binds them): one texel a pixel of the renderer's
// viewport, whose origin in the window is voxelgiOrigin. The depth is read and written inside
// the interlock where the GPU has one.
layout(binding = VOXELGI_GBUFFER_DEPTH_UNIT, r32f) coherent uniform image2D gbufferDepthImage;
layout(binding = VOXELGI_GBUFFER_COLOR_UNIT, rgba16f) writeonly uniform image2D gbufferColorImage;
layout(binding = VOXELGI_GBUFFER_SURFACE_UNIT, rgb10_a2) writeonly uniform image2D gbufferSurfaceImage;
layout(binding = VOXELGI_GBUFFER_MATERIAL_UNIT, rgba8) writeonly uniform image2D gbufferMaterialImage;
layout(binding = VOXELGI_GBUFFER_AMBIENT_UNIT, r11f_g11f_b10f) writeonly uniform image2D gbufferAmbientImage;
uniform ivec2 voxelgiOrigin;
// The framebuffer's sample nearest the pixel's centre (the only one without multisampling).
uniform int voxelgiCentralSample;
#ifdef GL_ARB_fragment_shader_interlock
// Only fragments that share a sample wait for each other (adjacent triangles do not).
layout(sample_interlock_ordered) in;
#endif
