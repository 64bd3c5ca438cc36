//! Pictures painted for the command line and the window: egui's triangles on the CPU
//! ([`egui_cpu`]: charts as PNGs, the whole window headless) and the scene's generated WGSL
//! on the GPU through wgpu ([`gpu`]).

pub mod cost_chart;
pub mod egui_cpu;
pub mod gpu;
