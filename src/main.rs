//! The `softgl` command: renders the built-in demo scene, or an OBJ model
//! with its materials and textures ([`render`]), to a PNG.

mod render;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "softgl",
    version,
    about = "Software OpenGL 1.x renderer for offscreen rendering"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render the built-in demo scene to a PNG file.
    Demo {
        /// Output PNG path.
        #[arg(short, long, default_value = "demo.png")]
        output: PathBuf,
        /// Image size as WIDTHxHEIGHT (each 1..=16384).
        #[arg(long, default_value = "800x600", value_parser = parse_size)]
        size: (u32, u32),
    },
    /// Render a Wavefront OBJ model (with its MTL materials and diffuse
    /// textures) to a PNG file, framed and lit.
    Render {
        /// The .obj file.
        model: PathBuf,
        /// Output PNG path.
        #[arg(short, long)]
        output: PathBuf,
        /// Image size as WIDTHxHEIGHT (each 1..=16384).
        #[arg(long, default_value = "800x600", value_parser = parse_size)]
        size: (u32, u32),
    },
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let err = || format!("size must be WIDTHxHEIGHT with each side in 1..=16384, got {s:?}");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(err)?;
    let side = |v: &str| {
        v.trim()
            .parse::<u32>()
            .ok()
            .filter(|v| (1..=16384).contains(v))
            .ok_or_else(err)
    };
    Ok((side(w)?, side(h)?))
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Demo { output, size: (w, h) } => {
            let mut gl = match softgl::demo::render(w, h) {
                Ok(gl) => gl,
                Err(e) => {
                    eprintln!("softgl: cannot render the demo at {w}x{h}: {e}");
                    return ExitCode::FAILURE;
                }
            };
            if let Err(e) = gl
                .framebuffer()
                .to_rgba_image()
                .save_with_format(&output, image::ImageFormat::Png)
            {
                eprintln!("softgl: cannot write {}: {e}", output.display());
                return ExitCode::FAILURE;
            }
            println!("wrote {} ({w}x{h})", output.display());
            ExitCode::SUCCESS
        }
        Command::Render {
            model,
            output,
            size: (w, h),
        } => {
            let result = render::load(&model).and_then(|m| Ok((render::render(&m, w, h)?, m)));
            let (image, m) = match result {
                Ok(r) => r,
                Err(e) => {
                    eprintln!("softgl: {e}");
                    return ExitCode::FAILURE;
                }
            };
            if let Err(e) = image.save_with_format(&output, image::ImageFormat::Png) {
                eprintln!("softgl: cannot write {}: {e}", output.display());
                return ExitCode::FAILURE;
            }
            println!(
                "wrote {} ({w}x{h}): {} triangles, {} textured meshes",
                output.display(),
                m.triangles(),
                m.textured_meshes()
            );
            ExitCode::SUCCESS
        }
    }
}
