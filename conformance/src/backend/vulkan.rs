//! lavapipe through Vulkan (placeholder until the ash back end lands).

use super::Outcome;
use crate::scenes::Recording;

pub fn render(_rec: &Recording, _runs: usize) -> (Outcome, String) {
    (Outcome::Failed("lavapipe back end not built yet".into()), String::new())
}
