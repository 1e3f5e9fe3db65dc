/**
 * The software profile (vtkVoxelGIPass::SoftwareProfile): where OpenGL runs on the CPU, the
 * defaults take tens of seconds for a first image and seconds for a camera move; the profile
 * caps the frame's settings so that GI answers in about a second. The pass's own settings
 * stay as they are. GL-free.
 */
#ifndef VoxelGISoftwareProfile_h
#define VoxelGISoftwareProfile_h

#include "SettingsSnapshot.h" // voxelgi::Settings

#include <string>

namespace voxelgi
{

/// Whether a context's GL_RENDERER string names a renderer that runs on the CPU (Mesa's
/// llvmpipe and softpipe, OpenSWR, SwiftShader, Microsoft's GDI and basic render drivers).
bool IsSoftwareRenderer(const std::string& renderer);

/// Whether the profile applies with the setting `profile` (SOFTWARE_PROFILE_*) on a context
/// that is (`software`) or is not a software renderer.
bool SoftwareProfileApplies(int profile, bool software);

/// Caps `settings` to the profile: at most 64^3 voxels, 4 diffuse cones, a quarter trace
/// resolution and 256^2 shadow maps.
void ApplySoftwareProfile(Settings& settings);

}

#endif
