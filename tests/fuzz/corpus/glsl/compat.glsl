#version 120
varying vec4 col;
void main() { col = gl_Color * gl_LightSource[0].diffuse; gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }
//FRAGMENT
#version 120
varying vec4 col;
uniform int n;
void main() {
  float a[4];
  for (int i = 0; i < 4; ++i) a[i] = float(i);
  int j = n / (n - n);
  if (col.x > 0.5) discard;
  gl_FragColor = col * a[j] + vec4(float(n % 3));
}
