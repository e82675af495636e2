//! `edgepaint emit` (owned by the hardware-flow work; placeholder until it lands).

/// Arguments of `edgepaint emit`.
#[derive(clap::Args)]
pub struct Args {}

pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`emit` is not built yet")
}
pub fn run_default() -> anyhow::Result<()> { anyhow::bail!("emission is not built yet") }
