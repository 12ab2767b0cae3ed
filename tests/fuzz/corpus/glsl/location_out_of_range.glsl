#version 330
layout(location =40) in vec4 p;
void main() { gl_Position = p; }
