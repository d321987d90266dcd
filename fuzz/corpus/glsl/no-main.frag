varying vec2 st;
float f(float x) { return x; }
