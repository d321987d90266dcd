// OpenGL ES Pixel Shaders Tutorial, "Procedural Textures: Smooth Noise": the spoiler's
// half-neighbour filter (the centre 1/2, the four edge
// neighbours 1/8 each), with the section's main() at 8 tiles ("Reduce your number of tiles
// to 8."), no discard.
float smoothNoise(vec2 p) {
  vec2 nn = vec2(p.x, p.y+1.);
  vec2 ee = vec2(p.x+1., p.y);
  vec2 ss = vec2(p.x, p.y-1.);
  vec2 ww = vec2(p.x-1., p.y);
  vec2 cc = vec2(p.x, p.y);

  float sum = 0.;
  sum += randomNoise(nn)/8.;
  sum += randomNoise(ee)/8.;
  sum += randomNoise(ss)/8.;
  sum += randomNoise(ww)/8.;
  sum += randomNoise(cc)/2.;

  return sum;
}

void main(void) {
    vec2 position = gl_FragCoord.xy/uResolution.xx;
    float tiles = 8.;
    position = floor(position*tiles);
    float n = smoothNoise(position);
    gl_FragColor = vec4(vec3(n), 1.);
}
