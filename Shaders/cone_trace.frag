//VTK::System::Dec
// Per-pixel voxel cone tracing and composite. From the G-buffer it reconstructs each pixel's
// position (depth) in grid coordinates, traces diffuse cones over the normal's hemisphere,
// one specular cone whose aperture follows the specular power, and a narrow cone toward each
// light for soft shadows. VTK's shaded colour is kept as the direct term: the part of each
// shadowed light's contribution (VTK's Phong model) that the cone finds occluded is removed;
// indirect diffuse x albedo and indirect specular are added; AO darkens the direct term.
in vec2 texCoord;

#include "lights.glsl"
#include "cone_tracing.glsl"

uniform sampler2D gbufferColor;
uniform sampler2D gbufferNormal;
uniform sampler2D gbufferMaterial;
uniform sampler2D gbufferDepth;
uniform mat4 voxelFromNDC;      // normalized device coordinates -> grid coordinates
uniform mat3 normalToGrid;      // view-space normals -> grid directions
uniform vec3 coneDirections[16];
uniform int coneCount;
uniform float diffuseTanHalf;
uniform float maxDistance;      // voxels
uniform float startOffset;      // voxels along the normal, against self-illumination
uniform float indirectIntensity;
uniform float specularIntensity;
uniform int specularCone;
uniform float aoStrength;
uniform float aoFalloff;
uniform int coneShadows;
uniform float shadowTanHalf;
uniform int compositeView;      // 0 composite, 1 direct only, 2 indirect only, 3 AO only

//VTK::Output::Dec

// Half-angle tangent of a cone matching VTK's Phong lobe of this specular power.
float specularTanHalf(float power)
{
  return clamp(tan(sqrt(2.0 / (max(power, 0.0) + 2.0))), 0.02, 1.2);
}

void main()
{
  vec4 color = texture(gbufferColor, texCoord);
  float depth = texture(gbufferDepth, texCoord).r;
  if (depth >= 1.0)
  {
    gl_FragData[0] = compositeView == 0 || compositeView == 1 ? color : vec4(compositeView == 3 ? vec3(1.0) : vec3(0.0), color.a);
    gl_FragData[1] = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec2 ndc = texCoord * 2.0 - 1.0;
  vec4 ph = voxelFromNDC * vec4(ndc, depth * 2.0 - 1.0, 1.0);
  vec3 p = ph.xyz / ph.w;
  vec4 nearH = voxelFromNDC * vec4(ndc, -1.0, 1.0);
  vec4 farH = voxelFromNDC * vec4(ndc, 1.0, 1.0);
  vec3 viewDir = normalize(farH.xyz / farH.w - nearH.xyz / nearH.w);

  vec4 normalSpec = texture(gbufferNormal, texCoord);
  vec3 n = normalSpec.xyz;
  if (dot(n, n) < 0.25)
  {
    // VTK computed no normal (unlit actor): take the depth surface's own.
    n = cross(dFdx(p), dFdy(p));
    n = dot(n, n) > 0.0 ? normalize(n) : -viewDir;
  }
  else
  {
    n = normalize(normalToGrid * n);
  }
  if (dot(n, viewDir) > 0.0)
  {
    n = -n;
  }
  vec4 material = texture(gbufferMaterial, texCoord);
  vec3 albedo = material.rgb;
  float specular = material.a;
  vec3 origin = p + n * startOffset;

  vec3 t, b;
  voxelBasis(n, t, b);
  vec3 gathered = vec3(0.0);
  float occlusion = 0.0;
  for (int i = 0; i < coneCount; ++i)
  {
    vec3 d = normalize(coneDirections[i].x * t + coneDirections[i].y * b + coneDirections[i].z * n);
    float coneOcclusion;
    gathered += voxelConeTrace(origin, d, diffuseTanHalf, 1.0, maxDistance, aoFalloff, p, n, coneOcclusion).rgb;
    occlusion += coneOcclusion;
  }
  gathered /= float(max(coneCount, 1));
  float ao = 1.0 - occlusion / float(max(coneCount, 1));
  vec3 indirect = albedo * gathered * indirectIntensity;

  if (specularCone != 0 && specular > 0.0)
  {
    vec3 r = reflect(viewDir, n);
    float ignored;
    indirect += specular * specularIntensity *
      voxelConeTrace(origin, r, specularTanHalf(normalSpec.w), 1.0, maxDistance, 0.0, p, n, ignored).rgb;
  }

  vec3 direct = color.rgb;
  if (coneShadows != 0)
  {
    for (int l = 0; l < voxelLightInfo.x; ++l)
    {
      if (voxelLights[l].attenuation.w != 0.0)
      {
        continue; // a headlight's shadows are hidden behind what casts them
      }
      vec3 toLight;
      float distance;
      float attenuation = voxelLightIncidence(l, p, toLight, distance);
      float df = attenuation * dot(n, toLight);
      if (!(df > 0.0))
      {
        continue;
      }
      // Toward a grazing light the cone runs along its own surface's voxels: start it where
      // it has risen a voxel and a half above the surface.
      float start = max(1.0, 1.5 / max(dot(n, toLight), 0.1));
      // Stop short of the light by the cone's width there, so that geometry next to the light
      // (the ceiling a lamp hangs from) does not shadow everything it lights.
      float end = min(distance - max(2.0, 2.0 * shadowTanHalf * distance), maxDistance);
      float shadow;
      voxelConeTrace(origin, toLight, shadowTanHalf, start, end, 0.0, p, n, shadow);
      float sf = attenuation * pow(max(dot(reflect(-toLight, n), -viewDir), 0.0), normalSpec.w);
      vec3 contribution = (df * albedo + sf * specular) * voxelLights[l].color.rgb;
      direct -= shadow * contribution;
    }
    direct = max(direct, vec3(0.0));
  }
  direct *= mix(1.0, ao, aoStrength);

  vec3 result = direct + indirect;
  if (compositeView == 1)
  {
    result = direct;
  }
  else if (compositeView == 2)
  {
    result = indirect;
  }
  else if (compositeView == 3)
  {
    result = vec3(ao);
  }
  // Never let a non-finite value through to the image.
  result = (any(isnan(result)) || any(isinf(result))) ? vec3(0.0) : result;
  gl_FragData[0] = vec4(result, color.a);
  gl_FragData[1] = vec4(indirect, ao);
}
