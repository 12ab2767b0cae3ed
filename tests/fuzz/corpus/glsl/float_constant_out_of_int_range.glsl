#version 330
uniform mat4 MVP;
layout(location = 0) in vec4 p;
out vec3 n;
void main() { n = p.xyz; gl_Position = MVP * p + p; }
//FRAGMENT
#version 330
in vec3 n;
uniform sampler2D t;
uniform float k[3];
out vec4 c;
void main() {
  vec3 N = normalize(n);
  float s = 0.0;
  for (int i = 0; i < 10; ++i)//FRAGMENT >[i % 3]; }
  c = vec4(N * s, 1.0) * texture(t, n.xy) + vec4(pow(max(dot(N, N), 05555555555555555555555555555555555555555555555555555555555555555555555555555555555555555555555555555555555555555555.0), 8.0));
}
