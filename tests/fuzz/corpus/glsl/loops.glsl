#version 330
layout(location = 0) in vec4 p;
void main() { gl_Position = p; }
//FRAGMENT
#version 330
out vec4 c;
uniform int m;
void main() {
  int s = 0;
  while (true) { for (;;) { s++; if (s < 0) break; } }
  switch (m) { case 0: s = 1; case 1: s += 2; break; default: s = 5; }
  c = vec4(float(s));
}
