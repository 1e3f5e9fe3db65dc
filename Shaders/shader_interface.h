/* Constants and binding points shared by the C++ stages and the GLSL shaders. The stages
   include this file; the shader embedder (EmbedShaders.cmake) puts it in front of every
   embedded shader. Plain preprocessor definitions only, so that both languages read it. The
   uniform blocks are declared once for both languages too, in the *_block.h headers (see
   shader_interop.h). */
#ifndef VOXELGI_SHADER_INTERFACE
#define VOXELGI_SHADER_INTERFACE

#define VOXELGI_MAX_LIGHTS 16 /* lights in the light block */
#define VOXELGI_MAX_SHADOW_LAYERS 96 /* shadow maps: one per light, six for a point light */
#define VOXELGI_MAX_CONES 16  /* diffuse cone directions */
#define VOXELGI_LOCAL_SIZE 4  /* work group edge of the per-voxel compute stages */
#define VOXELGI_HALF_MAX 65504.0 /* largest finite half float: RGBA16F results stay below */

/* Uniform buffer binding points. */
#define VOXELGI_LIGHT_BLOCK_BINDING 0 /* lights.glsl */
#define VOXELGI_GRID_BLOCK_BINDING 1  /* voxel_grid.glsl */
#define VOXELGI_SHADOW_BLOCK_BINDING 2 /* shadow_maps.glsl */

/* Shader storage bindings 0, 1, ...: one per channel of the voxelization sums
   (voxel_common.glsl), count, albedo rgb, normal xyz, then when present emission rgb (the
   largest emitted radiance of the voxel's fragments, float bits) and the count of emitting
   fragments. */
#define VOXELGI_BASE_CHANNELS 7
#define VOXELGI_EMISSION_CHANNELS 4
/* When translucent surfaces are voxelized, one more channel: the sum of the fragments'
   quantized transparency (1 - opacity), at its own binding. */
#define VOXELGI_CLEARNESS_BINDING 17

/* Shader storage binding of the occupied-brick list (brick_list.glsl). A brick is one work
   group of the per-voxel stages, VOXELGI_LOCAL_SIZE^3 voxels: the resolve lists the occupied
   ones, and the clear and the bounce run on those alone (an indirect dispatch). */
#define VOXELGI_BRICK_LIST_BINDING 11

/* Shader storage binding of the bounces' sums (voxel_bounce.comp): per bounce and colour
   channel the whole grid's increment of radiance, then the ratio the last tail used. */
#define VOXELGI_BOUNCE_SUMS_BINDING 16
#define VOXELGI_MAX_BOUNCES 10

/* Shader storage bindings of compute voxelization (voxelize.comp): an actor's vertices,
   triangles' vertex indices and cell colours (SceneBuffers), and the list of its triangles
   that cover many pixel columns. */
#define VOXELGI_SCENE_VERTEX_BINDING 12
#define VOXELGI_SCENE_INDEX_BINDING 13
#define VOXELGI_LARGE_TRIANGLE_BINDING 14
#define VOXELGI_SCENE_CELL_COLOR_BINDING 15

/* Shader storage binding of the trace's list of pixels to trace again (cone_trace.comp):
   the pixels of reused tiles that could not take the last frame's result. */
#define VOXELGI_RETRACE_LIST_BINDING 18

/* Image units of the voxelization stage. */
#define VOXELGI_FLAG_IMAGE_UNIT 0

/* Image units of the G-buffer where VTK's own draw stores it (gbuffer_images.glsl). */
#define VOXELGI_GBUFFER_DEPTH_UNIT 1
#define VOXELGI_GBUFFER_COLOR_UNIT 2
#define VOXELGI_GBUFFER_SURFACE_UNIT 3
#define VOXELGI_GBUFFER_MATERIAL_UNIT 4
#define VOXELGI_GBUFFER_AMBIENT_UNIT 5

#endif
