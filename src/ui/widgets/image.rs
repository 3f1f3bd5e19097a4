//! Float images on screen: through the wgpu pipelines when they are installed, else colour-mapped
//! on the CPU into textures cached per panel.

use crate::model::ImageData;
use crate::ui::gpu::{self, DisplayRange, FloatImage};
use eframe::egui::{self, Color32, Pos2, Rect, Vec2};
use eframe::egui_wgpu;
use std::collections::HashMap;

/// Draws float images (and tells panels whether the GPU path is on, for their point splats).
pub struct ImageView {
    /// Whether the wgpu pipelines are installed (else images are colour-mapped on the CPU).
    gpu: bool,
    /// CPU textures for the fallback path, keyed per panel: (image version, range key, texture).
    textures: HashMap<egui::Id, (u64, [u32; 3], egui::TextureHandle)>,
}

impl ImageView {
    /// An image view drawing on the GPU when `gpu`, else on the CPU.
    pub fn new(gpu: bool) -> Self {
        ImageView {
            gpu,
            textures: HashMap::new(),
        }
    }

    /// Whether the wgpu pipelines are installed.
    pub fn gpu(&self) -> bool {
        self.gpu
    }

    /// Draws `image` through `range` in a `side`×`side` square; `window` = [u0, v0, du, dv]
    /// is the part of the image shown. `id` names the panel (its GPU resources or texture).
    /// Returns the square's rectangle.
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        id: egui::Id,
        image: &ImageData,
        range: DisplayRange,
        window: [f32; 4],
        side: f32,
    ) -> Rect {
        let (rect, _) = ui.allocate_exact_size(Vec2::splat(side), egui::Sense::hover());
        let float = FloatImage {
            width: image.width as u32,
            height: image.height as u32,
            values: image.values.clone(),
            version: image.version,
        };
        if self.gpu {
            let cb = gpu::ImageCallback {
                id,
                image: float,
                range,
                window,
            };
            ui.painter()
                .add(egui_wgpu::Callback::new_paint_callback(rect, cb));
        } else {
            let key = [
                range.lo.to_bits(),
                range.hi.to_bits(),
                range.colormap as u32,
            ];
            let entry = self.textures.get(&id);
            let fresh = entry.is_none_or(|(v, k, _)| *v != image.version || *k != key);
            if fresh {
                let ci = gpu::colorize(&float, range);
                let tex =
                    ui.ctx()
                        .load_texture(format!("{id:?}"), ci, egui::TextureOptions::NEAREST);
                self.textures.insert(id, (image.version, key, tex));
            }
            if let Some((_, _, tex)) = self.textures.get(&id) {
                let uv = Rect::from_min_size(
                    Pos2::new(window[0], window[1]),
                    Vec2::new(window[2], window[3]),
                );
                ui.painter().image(tex.id(), rect, uv, Color32::WHITE);
            }
        }
        rect
    }
}
