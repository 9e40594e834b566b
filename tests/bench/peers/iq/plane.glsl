// iq-style plane: the closed form a Shadertoy author writes for a plane, as in Inigo Quilez's
// article "Intersectors" (iquilezles.org/articles/intersectors, its plane): with the plane
// dot(n, p) + w = 0 and p = ro + t rd, t = -(dot(n, ro) + w) / dot(n, rd). Written here from that
// formula; no code is copied. What an author typically writes: the one division, no test of a ray
// parallel to the plane (there the division gives an infinity or, for an origin on the plane, 0/0,
// and the comparisons below turn both into a miss on IEEE hardware; GLSL ES does not promise it).
//
// Appended after shaders/raytrace.glsl (tests/bench/primitive-peers.js): the #define at the end
// makes the test and timing mains that follow call this in place of the project's intersectPlane.
// The project's conventions: vec4(t, n), t < 0 (MISS) on a miss, hits only for 0 < t < tMax.

vec4 iqPlane(vec3 ro, vec3 rd, vec4 plane, float tMax) {
    float t = -(dot(plane.xyz, ro) + plane.w) / dot(plane.xyz, rd);
    if (t > 0.0 && t < tMax) return vec4(t, plane.xyz);
    return MISS;
}

#define intersectPlane iqPlane
