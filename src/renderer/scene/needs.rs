use crate::task_set::TaskSet;
use crate::worksheet::TaskId;
use std::fmt;

/// What a scene needs: the worksheet tasks the renderer will call for it and the
/// subsystems it builds. Computed while loading; the renderer builds only these.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Needs {
    /// Tasks the renderer calls directly for this scene (integrator and materials).
    pub tasks: TaskSet,
    /// Triangles of the scene's meshes (a triangle BVH is built when > 0).
    pub triangles: usize,
    /// Hair fibre segments (a fibre BVH is built when > 0).
    pub fibre_segments: usize,
    /// Analytic spheres and quads (tested without a BVH).
    pub analytic_shapes: usize,
    /// Lights (a light sampler is built when > 0).
    pub lights: usize,
    /// Media (the volumetric path tracer runs when > 0, the surface path tracer otherwise).
    pub media: usize,
}

impl Needs {
    /// Every task the scene runs: [`Needs::tasks`] and, transitively, the tasks those call
    /// (from the task table's `needs`).
    pub fn all_tasks(&self) -> TaskSet {
        with_dependencies(self.tasks)
    }

    /// The integrator that renders the scene.
    pub fn integrator(&self) -> &'static str {
        if self.media > 0 {
            "volumetric path tracer (framework; free flights by the delta_tracking task)"
        } else {
            "path tracer (the path_trace task)"
        }
    }
}

/// `tasks` and every task they call through the task table's `needs`, transitively.
pub fn with_dependencies(tasks: TaskSet) -> TaskSet {
    let mut all = tasks;
    loop {
        let grown = all
            .iter()
            .flat_map(|t| t.info().needs.iter().copied())
            .fold(all, |mut set, t| {
                set.insert(t);
                set
            });
        if grown == all {
            return all;
        }
        all = grown;
    }
}

impl fmt::Display for Needs {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names = |set: TaskSet| {
            let v: Vec<&str> = set.iter().map(TaskId::name).collect();
            if v.is_empty() {
                "(none)".to_string()
            } else {
                v.join(", ")
            }
        };
        let indirect: TaskSet = self
            .all_tasks()
            .iter()
            .filter(|t| !self.tasks.contains(*t))
            .collect();
        writeln!(f, "tasks called:        {}", names(self.tasks))?;
        writeln!(f, "tasks those call:    {}", names(indirect))?;
        writeln!(f, "integrator:          {}", self.integrator())?;
        writeln!(f, "analytic shapes:     {}", self.analytic_shapes)?;
        let built = |n: usize, one: &str, many: &str| match n {
            0 => "no".to_string(),
            1 => format!("yes (1 {one})"),
            n => format!("yes ({n} {many})"),
        };
        writeln!(
            f,
            "triangle BVH:        {}",
            built(self.triangles, "triangle", "triangles")
        )?;
        writeln!(
            f,
            "fibre BVH:           {}",
            built(self.fibre_segments, "segment", "segments")
        )?;
        writeln!(
            f,
            "light sampler:       {}",
            built(self.lights, "light", "lights")
        )?;
        write!(
            f,
            "media:               {}",
            built(self.media, "medium", "media")
        )
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn counts_read_in_the_singular_for_one() {
        let needs = super::Needs {
            lights: 1,
            media: 2,
            ..Default::default()
        };
        let text = needs.to_string();
        assert!(
            text.contains("light sampler:       yes (1 light)"),
            "{text}"
        );
        assert!(
            text.contains("media:               yes (2 media)"),
            "{text}"
        );
        assert!(text.contains("triangle BVH:        no"), "{text}");
    }
}
