//! The lavapipe device: the loader, an instance, lavapipe's physical device
//! and queue, the render targets for one size (colour and depth-stencil
//! images, render pass, framebuffer), host-visible buffers, and teardown.

use crate::backend::child::Reference;
use crate::backend::Unavailable;
use ash::vk;
use std::collections::HashMap;

use super::plan::PipeKey;

/// A device, the render targets for one size, and compiled pipelines.
pub(super) struct Gpu {
    _entry: ash::Entry,
    pub(super) instance: ash::Instance,
    pub(super) device: ash::Device,
    pub(super) queue: vk::Queue,
    pub(super) name: String,
    pub(super) mem_props: vk::PhysicalDeviceMemoryProperties,
    pub(super) pool: vk::CommandPool,
    pub(super) cmd: vk::CommandBuffer,
    pub(super) fence: vk::Fence,
    pub(super) render_pass: vk::RenderPass,
    pub(super) framebuffer: vk::Framebuffer,
    pub(super) images: Vec<(vk::Image, vk::ImageView, vk::DeviceMemory)>,
    pub(super) readback: (vk::Buffer, vk::DeviceMemory),
    pub(super) layout: vk::PipelineLayout,
    pub(super) pipelines: HashMap<PipeKey, vk::Pipeline>,
    pub(super) width: u32,
    pub(super) height: u32,
}

pub(super) fn vk_err(what: &str) -> impl Fn(vk::Result) -> String + '_ {
    move |e| format!("{what}: {e}")
}

impl Gpu {
    pub(super) fn new(width: u32, height: u32) -> Result<Gpu, String> {
        let (entry, instance, pdev) = lavapipe().map_err(|e| e.to_string())?;
        // SAFETY: every Vulkan call below passes handles created here, and they
        // are destroyed in `Drop` in reverse order.
        unsafe {
            let props = instance.get_physical_device_properties(pdev);
            let name = props
                .device_name_as_c_str()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned();
            let family = instance
                .get_physical_device_queue_family_properties(pdev)
                .iter()
                .position(|q| q.queue_flags.contains(vk::QueueFlags::GRAPHICS))
                .ok_or("no graphics queue")? as u32;
            let features = vk::PhysicalDeviceFeatures::default().logic_op(true);
            let prio = [1.0];
            let qinfo = [vk::DeviceQueueCreateInfo::default()
                .queue_family_index(family)
                .queue_priorities(&prio)];
            let device = instance
                .create_device(
                    pdev,
                    &vk::DeviceCreateInfo::default()
                        .queue_create_infos(&qinfo)
                        .enabled_features(&features),
                    None,
                )
                .map_err(vk_err("vkCreateDevice"))?;
            let queue = device.get_device_queue(family, 0);
            let mem_props = instance.get_physical_device_memory_properties(pdev);
            let pool = device
                .create_command_pool(
                    &vk::CommandPoolCreateInfo::default()
                        .queue_family_index(family)
                        .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER),
                    None,
                )
                .map_err(vk_err("vkCreateCommandPool"))?;
            let cmd = device
                .allocate_command_buffers(
                    &vk::CommandBufferAllocateInfo::default()
                        .command_pool(pool)
                        .command_buffer_count(1),
                )
                .map_err(vk_err("vkAllocateCommandBuffers"))?[0];
            let fence = device
                .create_fence(&vk::FenceCreateInfo::default(), None)
                .map_err(vk_err("vkCreateFence"))?;
            let depth_format = [vk::Format::D24_UNORM_S8_UINT, vk::Format::D32_SFLOAT_S8_UINT]
                .into_iter()
                .find(|&f| {
                    instance
                        .get_physical_device_format_properties(pdev, f)
                        .optimal_tiling_features
                        .contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT)
                })
                .ok_or("no depth-stencil format")?;
            let mut gpu = Gpu {
                _entry: entry,
                instance,
                device,
                queue,
                name,
                mem_props,
                pool,
                cmd,
                fence,
                render_pass: vk::RenderPass::null(),
                framebuffer: vk::Framebuffer::null(),
                images: Vec::new(),
                readback: (vk::Buffer::null(), vk::DeviceMemory::null()),
                layout: vk::PipelineLayout::null(),
                pipelines: HashMap::new(),
                width,
                height,
            };
            gpu.targets(depth_format)?;
            Ok(gpu)
        }
    }

    fn memory_type(&self, bits: u32, flags: vk::MemoryPropertyFlags) -> Result<u32, String> {
        (0..self.mem_props.memory_type_count)
            .find(|&i| bits & (1 << i) != 0 && self.mem_props.memory_types[i as usize].property_flags.contains(flags))
            .ok_or_else(|| format!("no memory type {flags:?}"))
    }

    /// Device memory for `req` with `flags`; the caller binds it, and `Drop` frees it.
    fn allocate(
        &self,
        req: vk::MemoryRequirements,
        flags: vk::MemoryPropertyFlags,
    ) -> Result<vk::DeviceMemory, String> {
        let mem_type = self.memory_type(req.memory_type_bits, flags)?;
        // SAFETY: a valid allocation info on a live device.
        unsafe {
            self.device.allocate_memory(
                &vk::MemoryAllocateInfo::default()
                    .allocation_size(req.size)
                    .memory_type_index(mem_type),
                None,
            )
        }
        .map_err(vk_err("vkAllocateMemory"))
    }

    /// # Safety
    /// Called once, from `new`, with the device alive.
    unsafe fn targets(&mut self, depth_format: vk::Format) -> Result<(), String> {
        let d = &self.device;
        let extent = vk::Extent3D {
            width: self.width,
            height: self.height,
            depth: 1,
        };
        for (format, usage, aspect) in [
            (
                vk::Format::R8G8B8A8_UNORM,
                vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
                vk::ImageAspectFlags::COLOR,
            ),
            (
                depth_format,
                vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
                vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL,
            ),
        ] {
            // SAFETY: (for the block) valid create infos on a live device.
            let image = unsafe {
                d.create_image(
                    &vk::ImageCreateInfo::default()
                        .image_type(vk::ImageType::TYPE_2D)
                        .format(format)
                        .extent(extent)
                        .mip_levels(1)
                        .array_layers(1)
                        .samples(vk::SampleCountFlags::TYPE_1)
                        .tiling(vk::ImageTiling::OPTIMAL)
                        .usage(usage),
                    None,
                )
            }
            .map_err(vk_err("vkCreateImage"))?;
            // SAFETY: `image` was just created on this device.
            let req = unsafe { d.get_image_memory_requirements(image) };
            let memory = self.allocate(req, vk::MemoryPropertyFlags::DEVICE_LOCAL)?;
            // SAFETY: memory is bound once, to this image.
            let (memory, view) = unsafe {
                d.bind_image_memory(image, memory, 0)
                    .map_err(vk_err("vkBindImageMemory"))?;
                let view = d
                    .create_image_view(
                        &vk::ImageViewCreateInfo::default()
                            .image(image)
                            .view_type(vk::ImageViewType::TYPE_2D)
                            .format(format)
                            .subresource_range(
                                vk::ImageSubresourceRange::default()
                                    .aspect_mask(aspect)
                                    .level_count(1)
                                    .layer_count(1),
                            ),
                        None,
                    )
                    .map_err(vk_err("vkCreateImageView"))?;
                (memory, view)
            };
            self.images.push((image, view, memory));
        }
        let attachments = [
            vk::AttachmentDescription::default()
                .format(vk::Format::R8G8B8A8_UNORM)
                .samples(vk::SampleCountFlags::TYPE_1)
                .load_op(vk::AttachmentLoadOp::CLEAR)
                .store_op(vk::AttachmentStoreOp::STORE)
                .initial_layout(vk::ImageLayout::UNDEFINED)
                .final_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL),
            vk::AttachmentDescription::default()
                .format(depth_format)
                .samples(vk::SampleCountFlags::TYPE_1)
                .load_op(vk::AttachmentLoadOp::CLEAR)
                .store_op(vk::AttachmentStoreOp::DONT_CARE)
                .stencil_load_op(vk::AttachmentLoadOp::CLEAR)
                .stencil_store_op(vk::AttachmentStoreOp::DONT_CARE)
                .initial_layout(vk::ImageLayout::UNDEFINED)
                .final_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        ];
        let color_ref = [vk::AttachmentReference {
            attachment: 0,
            layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
        }];
        let depth_ref = vk::AttachmentReference {
            attachment: 1,
            layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
        };
        let subpass = [vk::SubpassDescription::default()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&color_ref)
            .depth_stencil_attachment(&depth_ref)];
        let views = [self.images[0].1, self.images[1].1];
        let bytes = self.width as u64 * self.height as u64 * 4;
        // SAFETY: valid create infos on a live device; handles are kept in `self` and freed in Drop.
        unsafe {
            self.render_pass = d
                .create_render_pass(
                    &vk::RenderPassCreateInfo::default()
                        .attachments(&attachments)
                        .subpasses(&subpass),
                    None,
                )
                .map_err(vk_err("vkCreateRenderPass"))?;
            self.framebuffer = d
                .create_framebuffer(
                    &vk::FramebufferCreateInfo::default()
                        .render_pass(self.render_pass)
                        .attachments(&views)
                        .width(self.width)
                        .height(self.height)
                        .layers(1),
                    None,
                )
                .map_err(vk_err("vkCreateFramebuffer"))?;
            self.layout = d
                .create_pipeline_layout(&vk::PipelineLayoutCreateInfo::default(), None)
                .map_err(vk_err("vkCreatePipelineLayout"))?;
        }
        self.readback = self.host_buffer(bytes, vk::BufferUsageFlags::TRANSFER_DST)?;
        Ok(())
    }

    pub(super) fn host_buffer(
        &self,
        size: u64,
        usage: vk::BufferUsageFlags,
    ) -> Result<(vk::Buffer, vk::DeviceMemory), String> {
        let d = &self.device;
        // SAFETY: valid create infos on a live device; the memory is bound once, to this buffer.
        unsafe {
            let buffer = d
                .create_buffer(&vk::BufferCreateInfo::default().size(size.max(4)).usage(usage), None)
                .map_err(vk_err("vkCreateBuffer"))?;
            let req = d.get_buffer_memory_requirements(buffer);
            let memory = self.allocate(
                req,
                vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
            )?;
            d.bind_buffer_memory(buffer, memory, 0)
                .map_err(vk_err("vkBindBufferMemory"))?;
            Ok((buffer, memory))
        }
    }
}

/// The Vulkan loader, an instance and lavapipe's physical device. Missing:
/// no loader, no Vulkan driver at all, or none of them lavapipe.
fn lavapipe() -> Result<(ash::Entry, ash::Instance, vk::PhysicalDevice), Unavailable> {
    let missing = || Unavailable::Missing(Reference::Lavapipe.needs());
    // SAFETY: loads the system's Vulkan loader (libvulkan.so.1); ash keeps it loaded in `Entry`.
    let entry = unsafe { ash::Entry::load() }.map_err(|_| missing())?;
    let app = vk::ApplicationInfo::default().api_version(vk::make_api_version(0, 1, 1, 0));
    // SAFETY: valid create info; the instance is destroyed here on failure, else by the caller.
    unsafe {
        let instance = match entry.create_instance(&vk::InstanceCreateInfo::default().application_info(&app), None) {
            Ok(i) => i,
            // The loader found no driver.
            Err(vk::Result::ERROR_INCOMPATIBLE_DRIVER) => return Err(missing()),
            Err(e) => return Err(Unavailable::Broken(format!("vkCreateInstance: {e}"))),
        };
        let devices = match instance.enumerate_physical_devices() {
            Ok(d) => d,
            Err(e) => {
                instance.destroy_instance(None);
                return Err(Unavailable::Broken(format!("vkEnumeratePhysicalDevices: {e}")));
            }
        };
        let pdev = devices.into_iter().find(|&p| {
            let props = instance.get_physical_device_properties(p);
            let name = props.device_name_as_c_str().unwrap_or_default().to_string_lossy();
            props.device_type == vk::PhysicalDeviceType::CPU && name.contains("llvmpipe")
        });
        match pdev {
            Some(p) => Ok((entry, instance, p)),
            None => {
                instance.destroy_instance(None);
                Err(missing())
            }
        }
    }
}

/// Whether lavapipe is there (for the child's probe).
pub fn installed() -> Result<(), Unavailable> {
    let (_entry, instance, _) = lavapipe()?;
    // SAFETY: the instance was just created and nothing else uses it.
    unsafe { instance.destroy_instance(None) };
    Ok(())
}

impl Drop for Gpu {
    fn drop(&mut self) {
        // SAFETY: every handle was created on this device/instance and is destroyed
        // once, after the device is idle, children before parents.
        unsafe {
            let d = &self.device;
            let _ = d.device_wait_idle();
            for (_, p) in self.pipelines.drain() {
                d.destroy_pipeline(p, None);
            }
            d.destroy_pipeline_layout(self.layout, None);
            d.destroy_buffer(self.readback.0, None);
            d.free_memory(self.readback.1, None);
            d.destroy_framebuffer(self.framebuffer, None);
            d.destroy_render_pass(self.render_pass, None);
            for (image, view, memory) in self.images.drain(..) {
                d.destroy_image_view(view, None);
                d.destroy_image(image, None);
                d.free_memory(memory, None);
            }
            d.destroy_fence(self.fence, None);
            d.destroy_command_pool(self.pool, None);
            d.destroy_device(None);
            self.instance.destroy_instance(None);
        }
    }
}
