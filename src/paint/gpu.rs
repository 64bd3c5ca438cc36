//! The generated WGSL drawn by wgpu: the program a scene compiles to
//! ([`phonglab_core::shader`]) run on a GPU, into an offscreen colour and depth target.
//!
//! One path for the app's shaded view (through an egui_wgpu paint callback, see
//! `app::gpu_view`) and for the tests that check it against the CPU renderer on wgpu's
//! software adapter. The CPU renderer ([`phonglab_core::render`]) stays the reference.
//!
//! | step | what |
//! |---|---|
//! | [`wgsl_for`] | the scene's program, Gouraud or Phong, from the specialised plan |
//! | [`uniform_bytes`] | its uniforms' values, laid out as WGSL lays out the `Uniforms` struct |
//! | [`Program`] | the compiled pipeline and its uniform buffer |
//! | [`MeshBuffers`] | positions and normals interleaved, triangles as 32-bit indices |
//! | [`Target`] | the colour (RGBA8, as the CPU renderer writes) and depth (32-bit float) textures |
//! | [`draw`] | clear to the background, depth test `<`, no culling: as the CPU renderer |
//! | [`read_rgba`] | the colour target back, rows top to bottom |

use std::future::Future;

use eframe::wgpu;
use eframe::wgpu::util::DeviceExt;
use phonglab_core::mesh::Mesh;
use phonglab_core::render::Job;
use phonglab_core::shader::{Shader, ShaderShading, ShadingLanguage, generate_for, uniform_value};
use phonglab_core::{EvalOptions, Scene, Shading};

/// The colour target's format: 8 bits per channel, no sRGB encoding, as the CPU renderer
/// writes its bytes (`round(255 * clamp(c))`).
pub const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
/// The depth target's format.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// OpenGL's clip space has z from -w to w, WebGPU's from 0 to w: `z' = (z + w) / 2`.
pub fn wgpu_from_gl_clip() -> glam::DMat4 {
    glam::DMat4::from_cols_array(&[1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.5, 1.0])
}

/// The generated WGSL module for `scene` (its key under `options`), or why there is none:
/// Flat shading, which the generator does not write, or a scene that does not evaluate.
pub fn wgsl_for(scene: &Scene, options: EvalOptions, shading: Shading) -> Result<Shader, String> {
    let shading = match shading {
        Shading::Gouraud => ShaderShading::Gouraud,
        Shading::Phong => ShaderShading::Phong,
        Shading::Flat => return Err("no program is generated for Flat shading".into()),
    };
    generate_for(scene, options, ShadingLanguage::Wgsl, shading).map_err(|e| e.to_string())
}

/// WGSL's uniform layout: the alignment of a member of GLSL type `ty` (a `mat3` is three
/// columns of 16 bytes, a `vec3` is aligned as a `vec4`).
fn align(ty: &str) -> usize {
    match ty {
        "mat4" | "mat3" | "vec4" | "vec3" => 16,
        _ => 4,
    }
}

/// The uniform buffer's bytes for a generated program's `uniforms` (`Shader::uniforms`),
/// drawing `scene` with `clip_from_object` in OpenGL's clip space (converted to WebGPU's
/// here). An error names a uniform the generator declared but has no value for.
pub fn uniform_bytes(
    uniforms: &[(String, &'static str)],
    scene: &Scene,
    clip_from_object: &glam::DMat4,
) -> Result<Vec<u8>, String> {
    let clip = wgpu_from_gl_clip() * *clip_from_object;
    let mut bytes: Vec<u8> = Vec::new();
    for (name, ty) in uniforms {
        while !bytes.len().is_multiple_of(align(ty)) {
            bytes.push(0);
        }
        let v = uniform_value(scene, &clip, name).ok_or_else(|| format!("the uniform u_{name} has no value"))?;
        if *ty == "mat3" {
            for col in v.chunks(3) {
                for x in col.iter().chain([0.0f32].iter()) {
                    bytes.extend_from_slice(&x.to_le_bytes());
                }
            }
        } else {
            for x in &v {
                bytes.extend_from_slice(&x.to_le_bytes());
            }
        }
    }
    while bytes.is_empty() || !bytes.len().is_multiple_of(16) {
        bytes.push(0);
    }
    Ok(bytes)
}

/// Runs `f` inside a validation error scope: wgpu's errors become an `Err` instead of
/// reaching the device's uncaptured-error handler (which panics).
fn catching<T>(device: &wgpu::Device, f: impl FnOnce() -> T) -> Result<T, String> {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let value = f();
    let mut future = std::pin::pin!(scope.pop());
    // On native backends the scope's future is ready at once.
    match future.as_mut().poll(&mut std::task::Context::from_waker(std::task::Waker::noop())) {
        std::task::Poll::Ready(Some(e)) => Err(e.to_string()),
        _ => Ok(value),
    }
}

/// A generated program compiled into a pipeline, with its uniform buffer.
pub struct Program {
    pipeline: wgpu::RenderPipeline,
    uniforms: wgpu::Buffer,
    bind: wgpu::BindGroup,
}

impl Program {
    /// Compiles `wgsl` (entry points `vs_main` and `fs_main`, uniforms at group 0 binding
    /// 0, `uniform_len` bytes) for [`COLOR_FORMAT`] and [`DEPTH_FORMAT`] targets.
    pub fn new(device: &wgpu::Device, wgsl: &str, uniform_len: usize) -> Result<Self, String> {
        catching(device, || {
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("phonglab generated WGSL"),
                source: wgpu::ShaderSource::Wgsl(wgsl.into()),
            });
            let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("phonglab generated"),
                layout: None,
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_main"),
                    compilation_options: Default::default(),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: 24,
                        step_mode: wgpu::VertexStepMode::Vertex,
                        attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
                    })],
                },
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_main"),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: COLOR_FORMAT,
                        blend: None,
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                // Both faces are drawn, as the CPU renderer draws them (two-sided lighting
                // shows the inside of the open cylinder).
                primitive: wgpu::PrimitiveState { cull_mode: None, ..Default::default() },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(wgpu::CompareFunction::Less),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: Default::default(),
                multiview_mask: None,
                cache: None,
            });
            let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("phonglab uniforms"),
                size: uniform_len as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: None,
                layout: &pipeline.get_bind_group_layout(0),
                entries: &[wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() }],
            });
            Program { pipeline, uniforms, bind }
        })
    }

    /// The uniform buffer's size in bytes.
    pub fn uniform_len(&self) -> usize {
        self.uniforms.size() as usize
    }

    /// Writes the uniforms' values (as [`uniform_bytes`] lays them out).
    pub fn write_uniforms(&self, queue: &wgpu::Queue, bytes: &[u8]) {
        queue.write_buffer(&self.uniforms, 0, bytes);
    }
}

/// A mesh on the GPU: position and normal interleaved (24 bytes a vertex), triangles as
/// 32-bit indices.
pub struct MeshBuffers {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

impl MeshBuffers {
    /// Uploads `mesh`.
    pub fn new(device: &wgpu::Device, mesh: &Mesh) -> Self {
        let mut vertices: Vec<u8> = Vec::with_capacity(mesh.positions.len() * 24);
        for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
            for x in [p.x, p.y, p.z, n.x, n.y, n.z] {
                vertices.extend_from_slice(&x.to_le_bytes());
            }
        }
        let indices: Vec<u8> = mesh.triangles.iter().flatten().flat_map(|i| i.to_le_bytes()).collect();
        let init = |contents: &[u8], usage| {
            // wgpu refuses an empty buffer; an empty mesh draws nothing anyway.
            let contents = if contents.is_empty() { &[0u8; 4][..] } else { contents };
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: None, contents, usage })
        };
        MeshBuffers {
            vertices: init(&vertices, wgpu::BufferUsages::VERTEX),
            indices: init(&indices, wgpu::BufferUsages::INDEX),
            index_count: (mesh.triangles.len() * 3) as u32,
        }
    }
}

/// The offscreen colour and depth textures, `size` pixels square.
pub struct Target {
    /// The colour texture ([`COLOR_FORMAT`]); it can be sampled (the app shows it) and
    /// copied (the tests read it).
    pub color: wgpu::Texture,
    depth: wgpu::Texture,
    /// Its side in pixels.
    pub size: u32,
}

impl Target {
    /// New textures of `size` pixels square.
    pub fn new(device: &wgpu::Device, size: u32) -> Self {
        let texture = |format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some("phonglab shaded view"),
                size: wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let color_usage = wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::TEXTURE_BINDING;
        Target {
            color: texture(COLOR_FORMAT, color_usage),
            depth: texture(DEPTH_FORMAT, wgpu::TextureUsages::RENDER_ATTACHMENT),
            size,
        }
    }
}

/// Records the drawing of `mesh` with `program` into `target`: cleared to `background`
/// (quantised to 8 bits as the CPU renderer writes it), depth cleared to 1, test `<`.
pub fn draw(
    encoder: &mut wgpu::CommandEncoder,
    program: &Program,
    mesh: &MeshBuffers,
    target: &Target,
    background: [f32; 3],
) {
    let bg = background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as f64 / 255.0);
    let color = target.color.create_view(&Default::default());
    let depth = target.depth.create_view(&Default::default());
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("phonglab shaded view"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: &color,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color { r: bg[0], g: bg[1], b: bg[2], a: 1.0 }),
                store: wgpu::StoreOp::Store,
            },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: &depth,
            depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
            stencil_ops: None,
        }),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    });
    if mesh.index_count > 0 {
        pass.set_pipeline(&program.pipeline);
        pass.set_bind_group(0, &program.bind, &[]);
        pass.set_vertex_buffer(0, mesh.vertices.slice(..));
        pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..mesh.index_count, 0, 0..1);
    }
}

/// Reads `target`'s colour back: RGBA8, rows top to bottom (`size * size * 4` bytes).
pub fn read_rgba(device: &wgpu::Device, queue: &wgpu::Queue, target: &Target) -> Result<Vec<u8>, String> {
    let size = target.size;
    let row = (size * 4).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
    let out = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: (row * size) as u64,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut enc = device.create_command_encoder(&Default::default());
    enc.copy_texture_to_buffer(
        target.color.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &out,
            layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: None },
        },
        wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 },
    );
    let idx = queue.submit(Some(enc.finish()));
    let slice = out.slice(..);
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |v| drop(tx.send(v)));
    device
        .poll(wgpu::PollType::Wait { submission_index: Some(idx), timeout: Some(std::time::Duration::from_secs(60)) })
        .map_err(|e| e.to_string())?;
    rx.recv().map_err(|e| e.to_string())?.map_err(|e| e.to_string())?;
    let data = slice.get_mapped_range().map_err(|e| e.to_string())?;
    let mut rgba = Vec::with_capacity((size * size * 4) as usize);
    for y in 0..size {
        let start = (y * row) as usize;
        rgba.extend_from_slice(&data[start..start + (size * 4) as usize]);
    }
    Ok(rgba)
}

/// Draws `job` with its generated WGSL at `size` pixels square and reads the picture back
/// (RGBA8, rows top to bottom): the one-shot path the tests compare with the CPU renderer.
/// Flat shading is refused (the generator writes Gouraud and Phong).
pub fn render(device: &wgpu::Device, queue: &wgpu::Queue, job: &Job<'_>, size: u32) -> Result<Vec<u8>, String> {
    let shader = wgsl_for(job.scene, job.options, job.mode.shading())?;
    let bytes = uniform_bytes(&shader.uniforms, job.scene, &job.clip_from_object)?;
    let program = Program::new(device, &shader.vertex, bytes.len())?;
    program.write_uniforms(queue, &bytes);
    let mesh = MeshBuffers::new(device, job.mesh);
    let target = Target::new(device, size);
    let mut enc = device.create_command_encoder(&Default::default());
    draw(&mut enc, &program, &mesh, &target, job.background);
    queue.submit(Some(enc.finish()));
    read_rgba(device, queue, &target)
}
