//! The shaded view drawn on the GPU: the scene's generated WGSL ([`crate::paint::gpu`]) run
//! through eframe's wgpu backend, as an egui_wgpu paint callback.
//!
//! The callback's `prepare` draws the mesh into an offscreen colour and depth target (the
//! egui render pass has no depth buffer), and its `paint` copies that picture into the
//! view's rectangle, pixel for pixel. The CPU renderer stays the reference: it draws when
//! the adapter is a software one (unless the GPU is asked for), when there is no wgpu
//! adapter (the tests, the CLI), and for what the generator does not write (Flat shading,
//! the approximate power functions under study).

use std::sync::{Arc, Mutex};

use eframe::egui_wgpu::{self, CallbackResources, CallbackTrait, RenderState, ScreenDescriptor};
use eframe::wgpu;
use phonglab_core::mesh::Mesh;
use phonglab_core::{Document, PowFn, Shading};

use crate::paint::gpu;

/// Which renderer draws the shaded view.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RendererChoice {
    /// The GPU when the adapter is a real one, else the CPU renderer.
    #[default]
    Auto,
    /// Always the CPU renderer (the reference).
    Cpu,
    /// The GPU whenever there is an adapter, a software one included.
    Gpu,
}

impl RendererChoice {
    /// Every choice, in menu order.
    pub const ALL: [RendererChoice; 3] = [RendererChoice::Auto, RendererChoice::Cpu, RendererChoice::Gpu];

    /// The menu's words.
    pub fn label(self) -> String {
        match self {
            RendererChoice::Auto => crate::t!("renderer-auto"),
            RendererChoice::Cpu => crate::t!("renderer-cpu"),
            RendererChoice::Gpu => crate::t!("renderer-gpu"),
        }
    }
}

/// The adapter eframe's wgpu backend runs on, as the view names it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GpuInfo {
    /// The adapter's name (`llvmpipe (LLVM 15...)`, `NVIDIA GeForce ...`).
    pub name: String,
    /// The graphics API (Vulkan, Metal, Dx12, Gl).
    pub backend: String,
    /// A CPU adapter (llvmpipe, lavapipe, WARP): the CPU renderer is as fast and is the
    /// reference.
    pub software: bool,
}

impl GpuInfo {
    /// Describes `info`.
    pub fn of(info: &wgpu::AdapterInfo) -> Self {
        GpuInfo {
            name: info.name.clone(),
            backend: format!("{:?}", info.backend),
            software: info.device_type == wgpu::DeviceType::Cpu,
        }
    }
}

/// Prepares `render_state` for the view's paint callbacks (the copy pipeline for its
/// target format) and says which adapter it is.
pub fn install(render_state: &RenderState) -> GpuInfo {
    let resources = Resources::new(&render_state.device, render_state.target_format);
    render_state.renderer.write().callback_resources.insert(resources);
    GpuInfo::of(&render_state.adapter.get_info())
}

/// Why the generated program cannot draw `doc`'s view with power function `pow`, or
/// `None` when it can.
pub fn cannot_draw(doc: &Document, pow: PowFn) -> Option<String> {
    if doc.view.shading == Shading::Flat {
        return Some(crate::t!("cpu-flat"));
    }
    if pow != PowFn::Exact {
        return Some(crate::t!("cpu-approximate-pow"));
    }
    None
}

/// Why `doc`'s view is drawn by the CPU renderer, or `None` when the GPU draws it.
pub fn why_cpu(gpu: Option<&GpuInfo>, choice: RendererChoice, doc: &Document, pow: PowFn) -> Option<String> {
    let Some(gpu) = gpu else {
        return Some(crate::t!("cpu-no-adapter"));
    };
    match choice {
        RendererChoice::Cpu => return Some(crate::t!("cpu-chosen")),
        RendererChoice::Auto if gpu.software => {
            return Some(crate::t!("cpu-software-adapter", adapter = &gpu.name));
        }
        _ => {}
    }
    cannot_draw(doc, pow)
}

/// What one GPU picture needs, built each frame by the view and handed to the callback.
pub struct GpuImage {
    /// Which picture (the main view, the corrected one): each keeps its own buffers.
    pub slot: u64,
    /// The generated WGSL module.
    pub wgsl: Arc<str>,
    /// The uniforms' bytes.
    pub uniforms: Vec<u8>,
    /// The mesh (uploaded again only when it is another mesh).
    pub mesh: Arc<Mesh>,
    /// The background colour.
    pub background: [f32; 3],
    /// The target's side in pixels.
    pub px: u32,
    /// Where a failure (the program refused by the driver) is reported back to the view,
    /// which then draws on the CPU and says why.
    pub error: Arc<Mutex<Option<String>>>,
}

/// The callback's resources kept in egui_wgpu's renderer: the copy pipeline and each
/// picture's program, mesh and target.
struct Resources {
    copy: wgpu::RenderPipeline,
    copy_layout: wgpu::BindGroupLayout,
    slots: std::collections::HashMap<u64, Slot>,
}

/// One picture's GPU state, rebuilt piece by piece as what it draws changes.
struct Slot {
    wgsl: Arc<str>,
    program: gpu::Program,
    mesh: Arc<Mesh>,
    buffers: gpu::MeshBuffers,
    target: gpu::Target,
    copy_bind: wgpu::BindGroup,
}

/// The copy of the offscreen picture into the view's rectangle: a triangle over the
/// viewport, each pixel loaded (not filtered) from the picture. On an sRGB target the
/// bytes are decoded first, so the screen shows the bytes the CPU renderer would.
fn copy_wgsl(srgb_target: bool) -> String {
    let decode = if srgb_target {
        "let c = select(pow((t.rgb + 0.055) / 1.055, vec3<f32>(2.4)), t.rgb / 12.92, t.rgb <= vec3<f32>(0.04045));"
    } else {
        "let c = t.rgb;"
    };
    format!(
        "@group(0) @binding(0) var picture: texture_2d<f32>;\n\
         struct Out {{ @builtin(position) pos: vec4<f32>, @location(0) uv: vec2<f32> }};\n\
         @vertex fn vs_main(@builtin(vertex_index) i: u32) -> Out {{\n\
             let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));\n\
             var o: Out;\n\
             o.pos = vec4<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, 0.0, 1.0);\n\
             o.uv = uv;\n\
             return o;\n\
         }}\n\
         @fragment fn fs_main(o: Out) -> @location(0) vec4<f32> {{\n\
             let size = vec2<f32>(textureDimensions(picture));\n\
             let at = vec2<i32>(clamp(floor(o.uv * size), vec2<f32>(0.0), size - 1.0));\n\
             let t = textureLoad(picture, at, 0);\n\
             {decode}\n\
             return vec4<f32>(c, 1.0);\n\
         }}\n"
    )
}

impl Resources {
    fn new(device: &wgpu::Device, target_format: wgpu::TextureFormat) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("phonglab view copy"),
            source: wgpu::ShaderSource::Wgsl(copy_wgsl(target_format.is_srgb()).into()),
        });
        let copy_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("phonglab view copy"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: false },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
                count: None,
            }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: None,
            bind_group_layouts: &[Some(&copy_layout)],
            immediate_size: 0,
        });
        let copy = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("phonglab view copy"),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_main"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: target_format,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            primitive: Default::default(),
            depth_stencil: None,
            multisample: Default::default(),
            multiview_mask: None,
            cache: None,
        });
        Resources { copy, copy_layout, slots: Default::default() }
    }

    /// Brings `picture`'s slot up to date, rebuilding each part only when what it holds
    /// changed: the program (another WGSL text), the target (another size), the mesh
    /// buffers (another mesh).
    fn update(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, p: &GpuImage) -> Result<&Slot, String> {
        let program = || gpu::Program::new(device, &p.wgsl, p.uniforms.len());
        let slot = match self.slots.entry(p.slot) {
            std::collections::hash_map::Entry::Occupied(e) => e.into_mut(),
            std::collections::hash_map::Entry::Vacant(e) => {
                let target = gpu::Target::new(device, p.px);
                e.insert(Slot {
                    wgsl: p.wgsl.clone(),
                    program: program()?,
                    mesh: p.mesh.clone(),
                    buffers: gpu::MeshBuffers::new(device, &p.mesh),
                    copy_bind: copy_bind(device, &self.copy_layout, &target),
                    target,
                })
            }
        };
        if slot.wgsl != p.wgsl || slot.program.uniform_len() != p.uniforms.len() {
            slot.program = program()?;
            slot.wgsl = p.wgsl.clone();
        }
        if slot.target.size != p.px {
            slot.target = gpu::Target::new(device, p.px);
            slot.copy_bind = copy_bind(device, &self.copy_layout, &slot.target);
        }
        if !Arc::ptr_eq(&slot.mesh, &p.mesh) {
            slot.buffers = gpu::MeshBuffers::new(device, &p.mesh);
            slot.mesh = p.mesh.clone();
        }
        slot.program.write_uniforms(queue, &p.uniforms);
        Ok(slot)
    }
}

/// The copy pipeline's binding of `target`'s colour texture.
fn copy_bind(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, target: &gpu::Target) -> wgpu::BindGroup {
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout,
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: wgpu::BindingResource::TextureView(&target.color.create_view(&Default::default())),
        }],
    })
}

impl CallbackTrait for GpuImage {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &ScreenDescriptor,
        encoder: &mut wgpu::CommandEncoder,
        resources: &mut CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(res) = resources.get_mut::<Resources>() else {
            *self.error.lock().unwrap_or_else(std::sync::PoisonError::into_inner) =
                Some("the GPU view was not installed".into());
            return Vec::new();
        };
        match res.update(device, queue, self) {
            Ok(slot) => gpu::draw(encoder, &slot.program, &slot.buffers, &slot.target, self.background),
            Err(e) => {
                res.slots.remove(&self.slot);
                *self.error.lock().unwrap_or_else(std::sync::PoisonError::into_inner) = Some(e);
            }
        }
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &CallbackResources,
    ) {
        let Some(res) = resources.get::<Resources>() else { return };
        let Some(slot) = res.slots.get(&self.slot) else { return };
        pass.set_pipeline(&res.copy);
        pass.set_bind_group(0, &slot.copy_bind, &[]);
        pass.draw(0..3, 0..1);
    }
}

/// Adds `picture` to be drawn in `rect`.
pub fn paint(ui: &egui::Ui, rect: egui::Rect, picture: GpuImage) {
    ui.painter().add(egui_wgpu::Callback::new_paint_callback(rect, picture));
}
