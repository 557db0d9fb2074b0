//! One Vulkan pipeline per GL state a draw needs ([`PipeKey`]): GL's enums
//! as Vulkan's, the WGSL shaders (flat or smooth colour, the alpha test as a
//! `discard`) compiled to SPIR-V by naga, and the pipeline cache.

use super::device::{vk_err, Gpu};
use super::plan::{PipeKey, Vertex};
use ash::vk;
use softgl::{BlendEquation, BlendFactor, CompareFunc, Face, LogicOp, StencilOp};

fn compare_op(f: CompareFunc) -> vk::CompareOp {
    match f {
        CompareFunc::Never => vk::CompareOp::NEVER,
        CompareFunc::Less => vk::CompareOp::LESS,
        CompareFunc::Equal => vk::CompareOp::EQUAL,
        CompareFunc::Lequal => vk::CompareOp::LESS_OR_EQUAL,
        CompareFunc::Greater => vk::CompareOp::GREATER,
        CompareFunc::Notequal => vk::CompareOp::NOT_EQUAL,
        CompareFunc::Gequal => vk::CompareOp::GREATER_OR_EQUAL,
        CompareFunc::Always => vk::CompareOp::ALWAYS,
    }
}

fn stencil_op(o: StencilOp) -> vk::StencilOp {
    match o {
        StencilOp::Keep => vk::StencilOp::KEEP,
        StencilOp::Zero => vk::StencilOp::ZERO,
        StencilOp::Replace => vk::StencilOp::REPLACE,
        StencilOp::Incr => vk::StencilOp::INCREMENT_AND_CLAMP,
        StencilOp::Decr => vk::StencilOp::DECREMENT_AND_CLAMP,
        StencilOp::Invert => vk::StencilOp::INVERT,
        StencilOp::IncrWrap => vk::StencilOp::INCREMENT_AND_WRAP,
        StencilOp::DecrWrap => vk::StencilOp::DECREMENT_AND_WRAP,
    }
}

fn blend_factor(f: BlendFactor) -> vk::BlendFactor {
    match f {
        BlendFactor::Zero => vk::BlendFactor::ZERO,
        BlendFactor::One => vk::BlendFactor::ONE,
        BlendFactor::SrcColor => vk::BlendFactor::SRC_COLOR,
        BlendFactor::OneMinusSrcColor => vk::BlendFactor::ONE_MINUS_SRC_COLOR,
        BlendFactor::DstColor => vk::BlendFactor::DST_COLOR,
        BlendFactor::OneMinusDstColor => vk::BlendFactor::ONE_MINUS_DST_COLOR,
        BlendFactor::SrcAlpha => vk::BlendFactor::SRC_ALPHA,
        BlendFactor::OneMinusSrcAlpha => vk::BlendFactor::ONE_MINUS_SRC_ALPHA,
        BlendFactor::DstAlpha => vk::BlendFactor::DST_ALPHA,
        BlendFactor::OneMinusDstAlpha => vk::BlendFactor::ONE_MINUS_DST_ALPHA,
        BlendFactor::ConstantColor => vk::BlendFactor::CONSTANT_COLOR,
        BlendFactor::OneMinusConstantColor => vk::BlendFactor::ONE_MINUS_CONSTANT_COLOR,
        BlendFactor::ConstantAlpha => vk::BlendFactor::CONSTANT_ALPHA,
        BlendFactor::OneMinusConstantAlpha => vk::BlendFactor::ONE_MINUS_CONSTANT_ALPHA,
        BlendFactor::SrcAlphaSaturate => vk::BlendFactor::SRC_ALPHA_SATURATE,
    }
}

fn blend_op(e: BlendEquation) -> vk::BlendOp {
    match e {
        BlendEquation::Add => vk::BlendOp::ADD,
        BlendEquation::Subtract => vk::BlendOp::SUBTRACT,
        BlendEquation::ReverseSubtract => vk::BlendOp::REVERSE_SUBTRACT,
        BlendEquation::Min => vk::BlendOp::MIN,
        BlendEquation::Max => vk::BlendOp::MAX,
    }
}

fn logic_op(o: LogicOp) -> vk::LogicOp {
    match o {
        LogicOp::Clear => vk::LogicOp::CLEAR,
        LogicOp::And => vk::LogicOp::AND,
        LogicOp::AndReverse => vk::LogicOp::AND_REVERSE,
        LogicOp::Copy => vk::LogicOp::COPY,
        LogicOp::AndInverted => vk::LogicOp::AND_INVERTED,
        LogicOp::Noop => vk::LogicOp::NO_OP,
        LogicOp::Xor => vk::LogicOp::XOR,
        LogicOp::Or => vk::LogicOp::OR,
        LogicOp::Nor => vk::LogicOp::NOR,
        LogicOp::Equiv => vk::LogicOp::EQUIVALENT,
        LogicOp::Invert => vk::LogicOp::INVERT,
        LogicOp::OrReverse => vk::LogicOp::OR_REVERSE,
        LogicOp::CopyInverted => vk::LogicOp::COPY_INVERTED,
        LogicOp::OrInverted => vk::LogicOp::OR_INVERTED,
        LogicOp::Nand => vk::LogicOp::NAND,
        LogicOp::Set => vk::LogicOp::SET,
    }
}

/// The WGSL of the shaders for a key: flat or smooth colour, and the alpha test.
fn wgsl(key: &PipeKey) -> String {
    let interp = if key.flat { "@interpolate(flat)" } else { "" };
    let test = match key.alpha {
        None => String::new(),
        Some((f, r)) => {
            let r = f32::from_bits(r);
            let cond = match f {
                CompareFunc::Never => "false".to_string(),
                CompareFunc::Always => "true".to_string(),
                f => {
                    let op = match f {
                        CompareFunc::Less => "<",
                        CompareFunc::Equal => "==",
                        CompareFunc::Lequal => "<=",
                        CompareFunc::Greater => ">",
                        CompareFunc::Notequal => "!=",
                        _ => ">=",
                    };
                    format!("i.color.a {op} {r:?}")
                }
            };
            format!("if (!({cond})) {{ discard; }}")
        }
    };
    format!(
        "struct VOut {{ @builtin(position) pos: vec4<f32>, @location(0) {interp} color: vec4<f32> }};
@vertex fn vs(@location(0) p: vec4<f32>, @location(1) c: vec4<f32>) -> VOut {{
    var o: VOut; o.pos = p; o.color = c; return o;
}}
@fragment fn fs(i: VOut) -> @location(0) vec4<f32> {{ {test} return i.color; }}"
    )
}

/// SPIR-V for one entry point of `src`.
fn spirv(src: &str, stage: naga::ShaderStage, entry: &str) -> Result<Vec<u32>, String> {
    let module = naga::front::wgsl::parse_str(src).map_err(|e| e.emit_to_string(src))?;
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::empty())
        .validate(&module)
        .map_err(|e| format!("{e:?}"))?;
    let options = naga::back::spv::Options {
        // Keep positions as given: the y flip is done on the CPU.
        flags: naga::back::spv::WriterFlags::empty(),
        ..Default::default()
    };
    let pipeline = naga::back::spv::PipelineOptions {
        shader_stage: stage,
        entry_point: entry.into(),
    };
    naga::back::spv::write_vec(&module, &info, &options, Some(&pipeline)).map_err(|e| e.to_string())
}

impl Gpu {
    /// The pipeline for `key`, compiled on first use.
    pub(super) fn pipeline(&mut self, key: &PipeKey) -> Result<vk::Pipeline, String> {
        if let Some(&p) = self.pipelines.get(key) {
            return Ok(p);
        }
        let src = wgsl(key);
        let vs = spirv(&src, naga::ShaderStage::Vertex, "vs")?;
        let fs = spirv(&src, naga::ShaderStage::Fragment, "fs")?;
        let d = &self.device;
        let stencil = vk::StencilOpState {
            fail_op: stencil_op(key.stencil_ops[0]),
            depth_fail_op: stencil_op(key.stencil_ops[1]),
            pass_op: stencil_op(key.stencil_ops[2]),
            compare_op: compare_op(key.stencil_func),
            compare_mask: key.stencil_value_mask,
            write_mask: key.stencil_write_mask,
            reference: key.stencil_ref,
        };
        let mut mask = vk::ColorComponentFlags::empty();
        for (on, bit) in key.color_mask.iter().zip([
            vk::ColorComponentFlags::R,
            vk::ColorComponentFlags::G,
            vk::ColorComponentFlags::B,
            vk::ColorComponentFlags::A,
        ]) {
            if *on {
                mask |= bit;
            }
        }
        let blend = [vk::PipelineColorBlendAttachmentState::default()
            .blend_enable(key.blend)
            .src_color_blend_factor(blend_factor(key.blend_factors[0]))
            .dst_color_blend_factor(blend_factor(key.blend_factors[1]))
            .src_alpha_blend_factor(blend_factor(key.blend_factors[2]))
            .dst_alpha_blend_factor(blend_factor(key.blend_factors[3]))
            .color_blend_op(blend_op(key.blend_equations[0]))
            .alpha_blend_op(blend_op(key.blend_equations[1]))
            .color_write_mask(mask)];
        let blend_state = vk::PipelineColorBlendStateCreateInfo::default()
            .logic_op_enable(key.logic_op.is_some())
            .logic_op(key.logic_op.map_or(vk::LogicOp::COPY, logic_op))
            .attachments(&blend)
            .blend_constants(key.blend_color.map(f32::from_bits));
        // Vulkan's framebuffer row r is GL's window row r, so the same
        // coordinates wind the other way in Vulkan's (y-down) convention.
        let front = if key.front_ccw {
            vk::FrontFace::CLOCKWISE
        } else {
            vk::FrontFace::COUNTER_CLOCKWISE
        };
        let cull = match key.cull {
            None => vk::CullModeFlags::NONE,
            Some(Face::Front) => vk::CullModeFlags::FRONT,
            Some(Face::Back) => vk::CullModeFlags::BACK,
            Some(Face::FrontAndBack) => vk::CullModeFlags::FRONT_AND_BACK,
        };
        let (factor, units) = key
            .offset
            .map_or((0.0, 0.0), |(f, u)| (f32::from_bits(f), f32::from_bits(u)));
        let raster = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(cull)
            .front_face(front)
            .depth_bias_enable(key.offset.is_some())
            .depth_bias_constant_factor(units)
            .depth_bias_slope_factor(factor)
            .line_width(1.0);
        let depth = vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(key.depth_test)
            .depth_write_enable(key.depth_test && key.depth_write)
            .depth_compare_op(compare_op(key.depth_func))
            .stencil_test_enable(key.stencil_test)
            .front(stencil)
            .back(stencil);
        let bindings = [vk::VertexInputBindingDescription {
            binding: 0,
            stride: std::mem::size_of::<Vertex>() as u32,
            input_rate: vk::VertexInputRate::VERTEX,
        }];
        let attrs = [
            vk::VertexInputAttributeDescription {
                location: 0,
                binding: 0,
                format: vk::Format::R32G32B32A32_SFLOAT,
                offset: 0,
            },
            vk::VertexInputAttributeDescription {
                location: 1,
                binding: 0,
                format: vk::Format::R32G32B32A32_SFLOAT,
                offset: 16,
            },
        ];
        let input = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(&bindings)
            .vertex_attribute_descriptions(&attrs);
        let assembly =
            vk::PipelineInputAssemblyStateCreateInfo::default().topology(vk::PrimitiveTopology::TRIANGLE_LIST);
        let viewport = vk::PipelineViewportStateCreateInfo::default()
            .viewport_count(1)
            .scissor_count(1);
        let ms = vk::PipelineMultisampleStateCreateInfo::default().rasterization_samples(vk::SampleCountFlags::TYPE_1);
        let dynamic = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
        let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic);
        // SAFETY: the SPIR-V came from naga's validated module; every create info points at
        // locals that outlive the calls; modules are destroyed once the pipeline exists.
        unsafe {
            let vm = d
                .create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&vs), None)
                .map_err(vk_err("vkCreateShaderModule"))?;
            let fm = d
                .create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&fs), None)
                .map_err(vk_err("vkCreateShaderModule"))?;
            let stages = [
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::VERTEX)
                    .module(vm)
                    .name(c"vs"),
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::FRAGMENT)
                    .module(fm)
                    .name(c"fs"),
            ];
            let info = vk::GraphicsPipelineCreateInfo::default()
                .stages(&stages)
                .vertex_input_state(&input)
                .input_assembly_state(&assembly)
                .viewport_state(&viewport)
                .rasterization_state(&raster)
                .multisample_state(&ms)
                .depth_stencil_state(&depth)
                .color_blend_state(&blend_state)
                .dynamic_state(&dynamic)
                .layout(self.layout)
                .render_pass(self.render_pass)
                .subpass(0);
            let p = d
                .create_graphics_pipelines(vk::PipelineCache::null(), &[info], None)
                .map_err(|(_, e)| format!("vkCreateGraphicsPipelines: {e}"))?[0];
            d.destroy_shader_module(vm, None);
            d.destroy_shader_module(fm, None);
            self.pipelines.insert(*key, p);
            Ok(p)
        }
    }
}
