//! The generated WGSL, run by wgpu on the machine's adapter (the software one here, as the
//! UI snapshot tests use), draws the benchmark scene as the CPU renderer does: identical
//! coverage up to the silhouette's edge pixels, and a mean difference over the covered
//! pixels within 1/255 per channel, Gouraud and Phong.

use eframe::wgpu;
use phonglab_core::explain::{Side, explain};
use phonglab_core::mesh::sphere;
use phonglab_core::render::Renderer;
use phonglab_core::shader::{Lang, ShaderShading, generate, uniform_value};
use phonglab_core::{Engine, EvalOptions, Shading, library, presets};

const SIZE: u32 = 256;

/// WGSL's uniform layout: the alignment of a member of GLSL type `ty` (a `mat3` takes
/// three columns of 16 bytes).
fn align(ty: &str) -> usize {
    match ty {
        "mat4" | "mat3" | "vec4" | "vec3" => 16,
        _ => 4,
    }
}

/// The uniform buffer's bytes for the generated module.
fn uniform_bytes(shader: &phonglab_core::shader::Shader, scene: &phonglab_core::Scene, clip: &glam::DMat4) -> Vec<u8> {
    let mut bytes: Vec<u8> = Vec::new();
    for (name, ty) in &shader.uniforms {
        while !bytes.len().is_multiple_of(align(ty)) {
            bytes.push(0);
        }
        let v = uniform_value(scene, clip, name).unwrap_or_else(|| panic!("no value for {name}"));
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
    while !bytes.len().is_multiple_of(16) {
        bytes.push(0);
    }
    bytes
}

/// The CPU renderer's image of `doc`'s shaded view, and the GPU's with the generated WGSL.
fn images_of(doc: &phonglab_core::Document, shading: ShaderShading) -> (Vec<u8>, Vec<u8>, [u8; 3]) {
    let mut doc = doc.clone();
    doc.view.shading = if shading == ShaderShading::Phong { Shading::Phong } else { Shading::Gouraud };
    let setup = doc.shaded_setup(phonglab_core::PowFn::Exact);
    let mesh = doc.view.mesh();
    let job = setup.job(&mesh);
    gpu_image(&job, shading)
}

fn bench_images(shading: ShaderShading) -> (Vec<u8>, Vec<u8>, [u8; 3]) {
    let scene = presets::bench_scene(10);
    let mesh = sphere::glu_sphere(1.0, 50, 50);
    let cpu_shading = if shading == ShaderShading::Phong { Shading::Phong } else { Shading::Gouraud };
    let job = library::bench_job(&scene, &mesh, cpu_shading);
    gpu_image(&job, shading)
}

fn gpu_image(job: &phonglab_core::render::Job<'_>, shading: ShaderShading) -> (Vec<u8>, Vec<u8>, [u8; 3]) {
    let (scene, mesh) = (job.scene, job.mesh);
    let mut r = Renderer::new();
    let cpu = r.render(job, SIZE as usize, SIZE as usize).unwrap().0.rgba.clone();
    let bg = job.background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);

    let lit = Engine::<f64>::new(scene).unwrap().light(&scene.vertex);
    let ex = explain(scene, &lit, Side::Front);
    let shader = generate(scene, EvalOptions::default(), &ex, Lang::Wgsl, shading);
    // OpenGL's clip z runs from -w to w, WebGPU's from 0 to w.
    let gl_to_wgpu =
        glam::DMat4::from_cols_array(&[1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.5, 1.0]);
    let clip = gl_to_wgpu * job.clip_from_object;
    let ubytes = uniform_bytes(&shader, scene, &clip);

    let rs = egui_kittest::wgpu::create_render_state(egui_kittest::wgpu::default_wgpu_setup(), Default::default());
    let (device, queue) = (&rs.device, &rs.queue);
    use wgpu::util::DeviceExt;
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("generated"),
        source: wgpu::ShaderSource::Wgsl(shader.vertex.clone().into()),
    });
    let mut vertices: Vec<f32> = Vec::new();
    for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
        vertices.extend_from_slice(&[p.x, p.y, p.z, n.x, n.y, n.z]);
    }
    let indices: Vec<u32> = mesh.triangles.iter().flatten().copied().collect();
    let as_bytes = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let vbuf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: &as_bytes(&vertices),
        usage: wgpu::BufferUsages::VERTEX,
    });
    let ibuf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: &indices.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>(),
        usage: wgpu::BufferUsages::INDEX,
    });
    let ubuf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: &ubytes,
        usage: wgpu::BufferUsages::UNIFORM,
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: None,
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
                format: wgpu::TextureFormat::Rgba8Unorm,
                blend: None,
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        primitive: wgpu::PrimitiveState { cull_mode: None, ..Default::default() },
        depth_stencil: Some(wgpu::DepthStencilState {
            format: wgpu::TextureFormat::Depth32Float,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: Default::default(),
        multiview_mask: None,
        cache: None,
    });
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[wgpu::BindGroupEntry { binding: 0, resource: ubuf.as_entire_binding() }],
    });
    let extent = wgpu::Extent3d { width: SIZE, height: SIZE, depth_or_array_layers: 1 };
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: extent,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8Unorm,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let depth = device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: extent,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Depth32Float,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    });
    let (tv, dv) = (target.create_view(&Default::default()), depth.create_view(&Default::default()));
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &tv,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color {
                        r: bg[0] as f64 / 255.0,
                        g: bg[1] as f64 / 255.0,
                        b: bg[2] as f64 / 255.0,
                        a: 1.0,
                    }),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &dv,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.set_vertex_buffer(0, vbuf.slice(..));
        pass.set_index_buffer(ibuf.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..indices.len() as u32, 0, 0..1);
    }
    let row = (SIZE * 4).div_ceil(256) * 256;
    let out = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: (row * SIZE) as u64,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    enc.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &out,
            layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: None },
        },
        extent,
    );
    let idx = queue.submit(Some(enc.finish()));
    let slice = out.slice(..);
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |v| drop(tx.send(v)));
    device
        .poll(wgpu::PollType::Wait { submission_index: Some(idx), timeout: Some(std::time::Duration::from_secs(30)) })
        .unwrap();
    rx.recv().unwrap().unwrap();
    let data = slice.get_mapped_range().unwrap();
    let mut gpu = Vec::with_capacity((SIZE * SIZE * 4) as usize);
    for y in 0..SIZE {
        let start = (y * row) as usize;
        gpu.extend_from_slice(&data[start..start + (SIZE * 4) as usize]);
    }
    (gpu, cpu, bg)
}

fn compare(what: &str, shading: ShaderShading, (gpu, cpu, bg): (Vec<u8>, Vec<u8>, [u8; 3])) {
    let covered = |img: &[u8], i: usize| img[i * 4..i * 4 + 3] != bg;
    let n = (SIZE * SIZE) as usize;
    let (mut both, mut only) = (0usize, 0usize);
    let mut sum = [0f64; 3];
    for i in 0..n {
        match (covered(&gpu, i), covered(&cpu, i)) {
            (true, true) => {
                both += 1;
                for c in 0..3 {
                    sum[c] += (gpu[i * 4 + c] as f64 - cpu[i * 4 + c] as f64).abs();
                }
            }
            (false, false) => {}
            _ => only += 1,
        }
    }
    let mad = sum.map(|s| s / both.max(1) as f64);
    println!("{what} {shading:?}: {both} pixels both, {only} in one only; MAD per channel {mad:?} (of 255)");
    assert!(both > 2_000, "{what}: {both}");
    assert!(only as f64 <= 0.01 * both as f64, "{what}: coverage differs on {only} pixels of {both}");
    assert!(mad.iter().all(|m| *m <= 1.0), "{what} {shading:?}: mean difference {mad:?} > 1/255");
}

#[test]
fn the_generated_wgsl_draws_what_the_cpu_renderer_draws() {
    for shading in [ShaderShading::Gouraud, ShaderShading::Phong] {
        compare("benchmark", shading, bench_images(shading));
    }
}

#[test]
fn so_it_does_for_the_shipped_scenes() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut docs = Vec::new();
    for f in [
        "spotlight.toml",
        "three-lights.toml",
        "worksheet-mview5.toml",
        "worksheet-mview2.toml",
        "redbook-teapots/11-gold.toml",
    ] {
        let doc = phonglab_core::Document::from_toml(&std::fs::read_to_string(root.join(f)).unwrap()).unwrap();
        docs.push((f.to_string(), doc));
    }
    // Two-sided lighting on the open cylinder, whose inside shows.
    let mut two = docs[0].1.clone();
    two.scene.light_model.two_sided = true;
    two.view.object = phonglab_core::ObjectKind::Cylinder;
    docs.push(("spotlight, two-sided, cylinder".into(), two));
    for (what, doc) in &docs {
        for shading in [ShaderShading::Gouraud, ShaderShading::Phong] {
            compare(what, shading, images_of(doc, shading));
        }
    }
}
