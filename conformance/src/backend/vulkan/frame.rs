//! One frame on the device: plan on the CPU, upload the vertices, record
//! the clears and draws, submit, wait, read the colour image back.

use super::device::{vk_err, Gpu};
use super::plan::{plan, Op, Vertex};
use crate::scenes::Recording;
use ash::vk;

impl Gpu {
    /// One frame: plan on the CPU, upload, record, submit, wait, read back.
    pub(super) fn frame(&mut self, rec: &Recording) -> Result<image::RgbaImage, String> {
        let plan = plan(rec)?;
        let mut pipes = Vec::new();
        for op in &plan.ops {
            if let Op::Draw { key, .. } = op {
                pipes.push(self.pipeline(key)?);
            }
        }
        let bytes = (plan.vertices.len() * std::mem::size_of::<Vertex>()) as u64;
        let vbuf = self.host_buffer(bytes, vk::BufferUsageFlags::VERTEX_BUFFER)?;
        let d = &self.device;
        let (w, h) = (self.width, self.height);
        // SAFETY: every handle is live; the mapped ranges are within the allocations
        // (`bytes` for the vertices, w*h*4 for the read-back); the queue is idle when
        // the fence has signalled, before the buffers are read or freed.
        let pixels = unsafe {
            if bytes > 0 {
                let p = d
                    .map_memory(vbuf.1, 0, bytes, vk::MemoryMapFlags::empty())
                    .map_err(vk_err("vkMapMemory"))?;
                std::ptr::copy_nonoverlapping(plan.vertices.as_ptr().cast::<u8>(), p.cast::<u8>(), bytes as usize);
                d.unmap_memory(vbuf.1);
            }
            d.reset_command_buffer(self.cmd, vk::CommandBufferResetFlags::empty())
                .map_err(vk_err("vkResetCommandBuffer"))?;
            d.begin_command_buffer(self.cmd, &vk::CommandBufferBeginInfo::default())
                .map_err(vk_err("vkBeginCommandBuffer"))?;
            let clears = [
                vk::ClearValue {
                    color: vk::ClearColorValue { float32: [0.0; 4] },
                },
                vk::ClearValue {
                    depth_stencil: vk::ClearDepthStencilValue { depth: 1.0, stencil: 0 },
                },
            ];
            let full = vk::Rect2D {
                offset: vk::Offset2D::default(),
                extent: vk::Extent2D { width: w, height: h },
            };
            d.cmd_begin_render_pass(
                self.cmd,
                &vk::RenderPassBeginInfo::default()
                    .render_pass(self.render_pass)
                    .framebuffer(self.framebuffer)
                    .render_area(full)
                    .clear_values(&clears),
                vk::SubpassContents::INLINE,
            );
            if bytes > 0 {
                d.cmd_bind_vertex_buffers(self.cmd, 0, &[vbuf.0], &[0]);
            }
            let mut pipes = pipes.into_iter();
            for op in &plan.ops {
                match *op {
                    Op::Clear {
                        rect,
                        color,
                        depth,
                        stencil,
                    } => {
                        let mut atts = Vec::new();
                        if let Some(c) = color {
                            atts.push(vk::ClearAttachment {
                                aspect_mask: vk::ImageAspectFlags::COLOR,
                                color_attachment: 0,
                                clear_value: vk::ClearValue {
                                    color: vk::ClearColorValue { float32: c },
                                },
                            });
                        }
                        let mut aspect = vk::ImageAspectFlags::empty();
                        if depth.is_some() {
                            aspect |= vk::ImageAspectFlags::DEPTH;
                        }
                        if stencil.is_some() {
                            aspect |= vk::ImageAspectFlags::STENCIL;
                        }
                        if !aspect.is_empty() {
                            atts.push(vk::ClearAttachment {
                                aspect_mask: aspect,
                                color_attachment: 0,
                                clear_value: vk::ClearValue {
                                    depth_stencil: vk::ClearDepthStencilValue {
                                        depth: depth.unwrap_or(1.0),
                                        stencil: stencil.unwrap_or(0),
                                    },
                                },
                            });
                        }
                        let r = [vk::ClearRect {
                            rect,
                            base_array_layer: 0,
                            layer_count: 1,
                        }];
                        d.cmd_clear_attachments(self.cmd, &atts, &r);
                    }
                    Op::Draw {
                        viewport,
                        scissor,
                        first,
                        count,
                        ..
                    } => {
                        let p = pipes.next().expect("one pipeline per draw");
                        d.cmd_bind_pipeline(self.cmd, vk::PipelineBindPoint::GRAPHICS, p);
                        d.cmd_set_viewport(self.cmd, 0, &[viewport]);
                        d.cmd_set_scissor(self.cmd, 0, &[scissor]);
                        d.cmd_draw(self.cmd, count, 1, first, 0);
                    }
                }
            }
            d.cmd_end_render_pass(self.cmd);
            let region = vk::BufferImageCopy::default()
                .image_subresource(
                    vk::ImageSubresourceLayers::default()
                        .aspect_mask(vk::ImageAspectFlags::COLOR)
                        .layer_count(1),
                )
                .image_extent(vk::Extent3D {
                    width: w,
                    height: h,
                    depth: 1,
                });
            d.cmd_copy_image_to_buffer(
                self.cmd,
                self.images[0].0,
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                self.readback.0,
                &[region],
            );
            d.end_command_buffer(self.cmd).map_err(vk_err("vkEndCommandBuffer"))?;
            let cmds = [self.cmd];
            d.queue_submit(
                self.queue,
                &[vk::SubmitInfo::default().command_buffers(&cmds)],
                self.fence,
            )
            .map_err(vk_err("vkQueueSubmit"))?;
            d.wait_for_fences(&[self.fence], true, u64::MAX)
                .map_err(vk_err("vkWaitForFences"))?;
            d.reset_fences(&[self.fence]).map_err(vk_err("vkResetFences"))?;
            let size = w as usize * h as usize * 4;
            let p = d
                .map_memory(self.readback.1, 0, size as u64, vk::MemoryMapFlags::empty())
                .map_err(vk_err("vkMapMemory"))?;
            // Row 0 is GL's bottom row: flip to top row first.
            let rows = std::slice::from_raw_parts(p.cast::<u8>(), size);
            let stride = w as usize * 4;
            let pixels: Vec<u8> = rows.chunks_exact(stride).rev().flatten().copied().collect();
            d.unmap_memory(self.readback.1);
            d.destroy_buffer(vbuf.0, None);
            d.free_memory(vbuf.1, None);
            pixels
        };
        image::RgbaImage::from_raw(w, h, pixels).ok_or_else(|| "read-back has the wrong size".into())
    }
}
