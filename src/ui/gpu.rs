//! wgpu display pipelines drawn through egui paint callbacks: point splats and float images
//! mapped through a colour map (`shaders/points.wgsl`, `shaders/colormap.wgsl`).
//!
//! Resources live in the renderer's `callback_resources`, keyed per panel, because every
//! `prepare` runs before any `paint`. Data are uploaded only when their version changes; a
//! change of display range or colour map rewrites a 48-byte uniform buffer.

use eframe::egui;
use eframe::egui_wgpu::{self, wgpu};
use std::collections::HashMap;
use std::sync::Arc;

/// Colour maps available for float images (the one colour map of [`crate::model`]).
use crate::model::Colormap;

/// How a float image is mapped to colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DisplayRange {
    /// Value mapped to the first colour.
    pub lo: f32,
    /// Value mapped to the last colour.
    pub hi: f32,
    /// Colour map.
    pub colormap: Colormap,
}

/// A float image to display: `width × height` values, row 0 at the top.
#[derive(Debug, Clone)]
pub struct FloatImage {
    pub width: u32,
    pub height: u32,
    pub values: Arc<Vec<f32>>,
    /// Changes whenever `values` change; uploads happen only then.
    pub version: u64,
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct PointUniforms {
    view: [f32; 4],
    radius: [f32; 2],
    edge: f32,
    _pad: f32,
    color: [f32; 4],
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct ImageUniforms {
    view: [f32; 4],
    range: [f32; 4],
    size: [f32; 4],
}

struct PointSlot {
    version: u64,
    capacity: usize,
    count: u32,
    buffer: wgpu::Buffer,
    uniforms: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

struct ImageSlot {
    version: u64,
    size: (u32, u32),
    colormap: Colormap,
    texture: wgpu::Texture,
    lut: wgpu::Texture,
    uniforms: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

/// Pipelines and per-panel resources, stored in `callback_resources`.
pub struct GpuResources {
    points_pipeline: wgpu::RenderPipeline,
    points_layout: wgpu::BindGroupLayout,
    image_pipeline: wgpu::RenderPipeline,
    image_layout: wgpu::BindGroupLayout,
    points: HashMap<egui::Id, PointSlot>,
    images: HashMap<egui::Id, ImageSlot>,
}

/// Creates the pipelines and registers them with the renderer. Returns an error (and the app
/// falls back to CPU drawing) if the device rejects them.
pub fn install(render_state: &egui_wgpu::RenderState) -> Result<(), String> {
    let device = &render_state.device;
    let format = render_state.target_format;
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let resources = create(device, format);
    if let Some(err) = pollster::block_on(scope.pop()) {
        return Err(format!("wgpu pipelines rejected: {err}"));
    }
    render_state
        .renderer
        .write()
        .callback_resources
        .insert(resources);
    Ok(())
}

fn create(device: &wgpu::Device, format: wgpu::TextureFormat) -> GpuResources {
    let blend = Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING);
    let uniform_entry = |binding, size: usize| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: std::num::NonZeroU64::new(size as u64),
        },
        count: None,
    };
    let pipeline = |label: &str,
                    shader: &wgpu::ShaderModule,
                    layout: &wgpu::BindGroupLayout,
                    buffers: &[Option<wgpu::VertexBufferLayout>]| {
        let pl = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(label),
            bind_group_layouts: &[Some(layout)],
            immediate_size: 0,
        });
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(label),
            layout: Some(&pl),
            vertex: wgpu::VertexState {
                module: shader,
                entry_point: Some("vs_main"),
                buffers,
                compilation_options: Default::default(),
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: shader,
                entry_point: Some("fs_main"),
                targets: &[Some(wgpu::ColorTargetState {
                    format,
                    blend,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
                compilation_options: Default::default(),
            }),
            multiview_mask: None,
            cache: None,
        })
    };

    let points_shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("samplescope points"),
        source: wgpu::ShaderSource::Wgsl(include_str!("../../shaders/points.wgsl").into()),
    });
    let points_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("samplescope points"),
        entries: &[uniform_entry(0, std::mem::size_of::<PointUniforms>())],
    });
    let points_pipeline = pipeline(
        "samplescope points",
        &points_shader,
        &points_layout,
        &[Some(wgpu::VertexBufferLayout {
            array_stride: 8,
            step_mode: wgpu::VertexStepMode::Instance,
            attributes: &wgpu::vertex_attr_array![0 => Float32x2],
        })],
    );

    let image_shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("samplescope colormap"),
        source: wgpu::ShaderSource::Wgsl(include_str!("../../shaders/colormap.wgsl").into()),
    });
    let texture_entry = |binding| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: false },
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    };
    let image_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("samplescope colormap"),
        entries: &[
            uniform_entry(0, std::mem::size_of::<ImageUniforms>()),
            texture_entry(1),
            texture_entry(2),
        ],
    });
    let image_pipeline = pipeline("samplescope colormap", &image_shader, &image_layout, &[]);

    GpuResources {
        points_pipeline,
        points_layout,
        image_pipeline,
        image_layout,
        points: HashMap::new(),
        images: HashMap::new(),
    }
}

/// Paint callback drawing points as discs.
pub struct PointsCallback {
    pub id: egui::Id,
    pub points: Arc<Vec<[f32; 2]>>,
    pub version: u64,
    /// How many of the points to draw (a prefix, for progressive sequences).
    pub count: u32,
    /// Visible window of the unit square: origin and size.
    pub window: [f32; 4],
    /// Disc radius in physical pixels.
    pub radius_px: f32,
    /// Colour (sRGB, unmultiplied).
    pub color: egui::Color32,
    /// Size of the callback rect in physical pixels.
    pub rect_px: [f32; 2],
}

impl egui_wgpu::CallbackTrait for PointsCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(res) = resources.get_mut::<GpuResources>() else {
            return Vec::new();
        };
        let n = self.points.len().max(1);
        let needs_new = res
            .points
            .get(&self.id)
            .is_none_or(|slot| slot.capacity < n);
        if needs_new {
            let capacity = n.next_power_of_two();
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("samplescope points"),
                size: (capacity * 8) as u64,
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("samplescope points uniforms"),
                size: std::mem::size_of::<PointUniforms>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("samplescope points"),
                layout: &res.points_layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: uniforms.as_entire_binding(),
                }],
            });
            res.points.insert(
                self.id,
                PointSlot {
                    version: u64::MAX,
                    capacity,
                    count: 0,
                    buffer,
                    uniforms,
                    bind_group,
                },
            );
        }
        let Some(slot) = res.points.get_mut(&self.id) else {
            return Vec::new();
        };
        if slot.version != self.version || needs_new {
            queue.write_buffer(&slot.buffer, 0, bytemuck::cast_slice(&self.points));
            slot.version = self.version;
        }
        slot.count = self.count.min(self.points.len() as u32);
        let [r, g, b, a] = self.color.to_srgba_unmultiplied().map(|c| c as f32 / 255.0);
        let w = self.window;
        let uniforms = PointUniforms {
            view: [w[0], w[1], 1.0 / w[2], 1.0 / w[3]],
            radius: [
                2.0 * self.radius_px / self.rect_px[0].max(1.0),
                2.0 * self.radius_px / self.rect_px[1].max(1.0),
            ],
            edge: self.radius_px.max(0.5),
            _pad: 0.0,
            color: [r * a, g * a, b * a, a],
        };
        queue.write_buffer(&slot.uniforms, 0, bytemuck::bytes_of(&uniforms));
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        let Some(res) = resources.get::<GpuResources>() else {
            return;
        };
        let Some(slot) = res.points.get(&self.id) else {
            return;
        };
        if slot.count == 0 {
            return;
        }
        pass.set_pipeline(&res.points_pipeline);
        pass.set_bind_group(0, &slot.bind_group, &[]);
        pass.set_vertex_buffer(0, slot.buffer.slice(..));
        pass.draw(0..6, 0..slot.count);
    }
}

/// Paint callback drawing a float image through a colour map.
pub struct ImageCallback {
    pub id: egui::Id,
    pub image: FloatImage,
    pub range: DisplayRange,
    /// Visible uv window (origin, size) for nearest-neighbour zoom.
    pub window: [f32; 4],
}

impl egui_wgpu::CallbackTrait for ImageCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(res) = resources.get_mut::<GpuResources>() else {
            return Vec::new();
        };
        let (w, h) = (self.image.width.max(1), self.image.height.max(1));
        if self.image.values.len() < (w * h) as usize {
            return Vec::new();
        }
        let needs_new = res.images.get(&self.id).is_none_or(|s| s.size != (w, h));
        if needs_new {
            let texture = device.create_texture(&wgpu::TextureDescriptor {
                label: Some("samplescope values"),
                size: wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::R32Float,
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            });
            let lut = device.create_texture(&wgpu::TextureDescriptor {
                label: Some("samplescope colormap"),
                size: wgpu::Extent3d {
                    width: 256,
                    height: 1,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::Rgba8Unorm,
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            });
            let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("samplescope colormap uniforms"),
                size: std::mem::size_of::<ImageUniforms>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let tv = texture.create_view(&Default::default());
            let lv = lut.create_view(&Default::default());
            let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("samplescope colormap"),
                layout: &res.image_layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: uniforms.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::TextureView(&tv),
                    },
                    wgpu::BindGroupEntry {
                        binding: 2,
                        resource: wgpu::BindingResource::TextureView(&lv),
                    },
                ],
            });
            res.images.insert(
                self.id,
                ImageSlot {
                    version: u64::MAX,
                    size: (w, h),
                    colormap: self.range.colormap,
                    texture,
                    lut,
                    uniforms,
                    bind_group,
                },
            );
            write_lut(queue, &res.images[&self.id].lut, self.range.colormap);
        }
        let Some(slot) = res.images.get_mut(&self.id) else {
            return Vec::new();
        };
        if slot.version != self.image.version {
            queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &slot.texture,
                    mip_level: 0,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                bytemuck::cast_slice(&self.image.values[..(w * h) as usize]),
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(4 * w),
                    rows_per_image: Some(h),
                },
                wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: 1,
                },
            );
            slot.version = self.image.version;
        }
        if slot.colormap != self.range.colormap {
            write_lut(queue, &slot.lut, self.range.colormap);
            slot.colormap = self.range.colormap;
        }
        let uniforms = ImageUniforms {
            view: self.window,
            range: [self.range.lo, self.range.hi, 0.0, 0.0],
            size: [w as f32, h as f32, 0.0, 0.0],
        };
        queue.write_buffer(&slot.uniforms, 0, bytemuck::bytes_of(&uniforms));
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        let Some(res) = resources.get::<GpuResources>() else {
            return;
        };
        let Some(slot) = res.images.get(&self.id) else {
            return;
        };
        pass.set_pipeline(&res.image_pipeline);
        pass.set_bind_group(0, &slot.bind_group, &[]);
        pass.draw(0..6, 0..1);
    }
}

fn write_lut(queue: &wgpu::Queue, lut: &wgpu::Texture, colormap: Colormap) {
    let data = colormap.lut();
    queue.write_texture(
        wgpu::TexelCopyTextureInfo {
            texture: lut,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        bytemuck::cast_slice(&data),
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(256 * 4),
            rows_per_image: Some(1),
        },
        wgpu::Extent3d {
            width: 256,
            height: 1,
            depth_or_array_layers: 1,
        },
    );
}

/// CPU colour mapping of a float image (the fallback when wgpu is unavailable): the one
/// colorizer of [`crate::model::colorize`].
pub fn colorize(image: &FloatImage, range: DisplayRange) -> egui::ColorImage {
    let (lo, hi) = (range.lo as f64, range.hi as f64);
    let rgb = crate::model::colorize(image.values.as_slice(), lo, hi, range.colormap);
    let pixels = rgb
        .chunks_exact(3)
        .map(|p| egui::Color32::from_rgb(p[0], p[1], p[2]))
        .collect();
    egui::ColorImage::new([image.width as usize, image.height as usize], pixels)
}
