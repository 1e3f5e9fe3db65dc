// Shadow maps hold depth alone (shadow_depth.vert).
void main()
{
}
