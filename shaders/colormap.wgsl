// Float image display: the value texture (R32Float, read with textureLoad, nearest) is mapped
// through a [lo, hi] window and a 256-entry colour map. Changing the window or the colour map
// only rewrites the uniforms: nothing is recomputed.

struct Uniforms {
    view: vec4<f32>,   // uv window: origin.xy, size.zw (nearest-neighbour zoom)
    range: vec4<f32>,  // lo, hi, unused, unused
    size: vec4<f32>,   // texture width, height, unused, unused
};

@group(0) @binding(0) var<uniform> u: Uniforms;
@group(0) @binding(1) var values: texture_2d<f32>;
@group(0) @binding(2) var lut: texture_2d<f32>;

struct VsOut {
    @builtin(position) pos: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vi: u32) -> VsOut {
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 0.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0),
    );
    let c = corners[vi % 6u];
    var out: VsOut;
    out.pos = vec4<f32>(c.x * 2.0 - 1.0, 1.0 - c.y * 2.0, 0.0, 1.0);
    out.uv = u.view.xy + c * u.view.zw;
    return out;
}

@fragment
fn fs_main(in: VsOut) -> @location(0) vec4<f32> {
    let w = i32(u.size.x);
    let h = i32(u.size.y);
    let x = clamp(i32(floor(in.uv.x * u.size.x)), 0, w - 1);
    let y = clamp(i32(floor(in.uv.y * u.size.y)), 0, h - 1);
    let v = textureLoad(values, vec2<i32>(x, y), 0).r;
    let t = clamp((v - u.range.x) / max(u.range.y - u.range.x, 1e-30), 0.0, 1.0);
    let i = i32(round(t * 255.0));
    return vec4<f32>(textureLoad(lut, vec2<i32>(i, 0), 0).rgb, 1.0);
}
