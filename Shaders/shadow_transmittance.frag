// A translucent surface of colour c and opacity a passes (1 - a) of the light that reaches
// it, tinted by its colour as much as it is opaque: (1 - a) mix(1, c, a). So a surface a
// lookup table hides (alpha 0) passes all of it, as VTK shows what lies behind it untinted,
// and an opaque one none (the reference renders it as a transparent BSDF of that colour and
// weight 1 - a over a diffuse one of weight a). The layer's blending multiplies
// the rgb of every translucent surface in front of the nearest opaque one (depth-tested
// against the layer's depth, not written), and keeps in alpha the largest 1 - depth: the
// nearest translucent surface, with half-float precision where perspective depth crowds
// towards 1 (shadow_maps.glsl's shadowMapTransmittance).
layout(std430, binding = VOXELGI_SCENE_CELL_COLOR_BINDING) readonly buffer TransmitCellColors
{
  uint transmitCellColors[];
};

uniform int transmitColorMode; // 0: the actor's colour and opacity, 1: per vertex, 2: per cell
uniform vec4 transmitColor;    // the actor's diffuse colour and opacity
in vec4 transmitVertexColor;
out vec4 transmitOut;

void main()
{
  vec4 c = transmitColorMode == 1
    ? transmitVertexColor
    : (transmitColorMode == 2 ? unpackUnorm4x8(transmitCellColors[gl_PrimitiveID]) : transmitColor);
  float a = clamp(c.a, 0.0, 1.0);
  transmitOut = vec4((1.0 - a) * mix(vec3(1.0), clamp(c.rgb, 0.0, 1.0), a), 1.0 - gl_FragCoord.z);
}
