//! `edgepaint report` (owned by the hardware-flow work; placeholder until it lands).

/// Arguments of `edgepaint report`.
#[derive(clap::Args)]
pub struct Args {}

pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`report` is not built yet")
}
