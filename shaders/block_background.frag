// The 3D view's backdrop: a quiet vertical gradient (drawn with image_plane.vert's full-screen triangle).
uniform vec3 u_top;
uniform vec3 u_bottom;
uniform float u_height;  // pixels
out vec4 fragColor;
void main() { fragColor = vec4(mix(u_bottom, u_top, gl_FragCoord.y / u_height), 1.0); }
