//! The scenes graded by rendering them ([`RENDER_CHECKS`]) and their points, the scenes'
//! share of the task table: the grader renders them (its `grade::renders`), `pbrlab tasks`
//! lists them.

/// A scene graded by rendering it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderCheck {
    /// The scene's file name in `scenes/`, without `.yaml`.
    pub scene: &'static str,
    /// Points the render is worth.
    pub points: f64,
}

/// The graded scenes: one per family of materials, so each needs a different set of tasks.
/// The hair scene is not among them: its fibres are thinner than a pixel at the graded size,
/// so a pixel's samples are hit-or-miss and far from normal at any affordable count (the
/// reference itself failed 0.6 % of its pixel-channels at 256 samples per pixel); the
/// `kajiya_kay` task is graded by its values.
pub const RENDER_CHECKS: [RenderCheck; 4] = [
    RenderCheck {
        scene: "cornell",
        points: 4.0,
    },
    RenderCheck {
        scene: "materials",
        points: 4.0,
    },
    RenderCheck {
        scene: "glass",
        points: 4.0,
    },
    RenderCheck {
        scene: "smoke",
        points: 4.0,
    },
];

/// The name a scene's render check has among the tasks in reports and the progress record
/// (`scene: cornell`).
pub fn scene_entry(scene: &str) -> String {
    format!("scene: {scene}")
}
