// Point splats: one instanced quad per sample point, antialiased disc in the fragment stage.
// Points are in the unit square (y up); `view` maps a window of the unit square onto the
// callback's viewport: q = (p - view.xy) * view.zw in [0,1]², then to NDC.

struct Uniforms {
    view: vec4<f32>,      // origin.xy, scale.zw
    radius_px: vec2<f32>, // disc radius in NDC units per axis (x, y)
    edge: f32,            // 1 / (antialiasing width in radius units)
    _pad: f32,
    color: vec4<f32>,     // premultiplied colour, gamma space
};

@group(0) @binding(0) var<uniform> u: Uniforms;

struct VsOut {
    @builtin(position) pos: vec4<f32>,
    @location(0) local: vec2<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vi: u32, @location(0) p: vec2<f32>) -> VsOut {
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, -1.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, 1.0), vec2<f32>(-1.0, 1.0),
    );
    let c = corners[vi % 6u];
    let q = (p - u.view.xy) * u.view.zw;
    let ndc = vec2<f32>(q.x * 2.0 - 1.0, q.y * 2.0 - 1.0) + c * u.radius_px;
    var out: VsOut;
    out.pos = vec4<f32>(ndc, 0.0, 1.0);
    out.local = c;
    return out;
}

@fragment
fn fs_main(in: VsOut) -> @location(0) vec4<f32> {
    let d = length(in.local);
    let a = clamp((1.0 - d) * u.edge, 0.0, 1.0);
    if (a <= 0.0) {
        discard;
    }
    return u.color * a;
}
