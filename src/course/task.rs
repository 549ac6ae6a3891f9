//! The worksheet's tasks: the one list of them ([`TaskId`]), and each one's row of the
//! task table ([`TASKS`]): its title, its worksheet sections, its points, the tasks it calls
//! and its hints. This is the one home of every task's points and hints: the grader, the
//! reports, `pbrlab tasks` and `pbrlab hint` read them here. The exercise file's header
//! (`exercises/<task>.rs`) is the task's text, read whole; the hints are what `pbrlab hint`
//! gives one level at a time, the last close to the answer. The task functions' signatures
//! are the renderer's (`pbrlab_renderer::worksheet`), whose `tasks!` list checks at compile
//! time that it names the same tasks in the same order.

/// Identifies one worksheet task. The discriminant is the task's index in [`TASKS`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum TaskId {
    /// Mirror reflection of a direction about a normal.
    Reflect,
    /// Snell's law, total internal reflection and a stack of refracting layers.
    RefractStack,
    /// R0 and Schlick's approximation of the Fresnel reflectance.
    FresnelSchlick,
    /// Cosine-weighted hemisphere sampling and its pdf.
    CosineSample,
    /// The GGX Smith masking function G1.
    SmithG1,
    /// The Cook-Torrance microfacet BRDF.
    CookTorrance,
    /// The anisotropic GGX normal distribution function.
    AnisoNdf,
    /// The Phong BRDF and a numerical reciprocity test.
    Phong,
    /// The Kajiya-Kay hair fibre model.
    KajiyaKay,
    /// The Beckmann normal distribution function.
    BeckmannNdf,
    /// Sampling reflected directions through the NDF, with the half-vector Jacobian.
    NdfSample,
    /// A numerical BRDF plausibility checker.
    BrdfCheck,
    /// One recursive step of a path tracer.
    PathTrace,
    /// Direct lighting by multiple importance sampling.
    Mis,
    /// Free-flight sampling by delta tracking.
    DeltaTracking,
}

impl TaskId {
    /// Every task, in worksheet order.
    pub const ALL: [TaskId; 15] = [
        TaskId::Reflect,
        TaskId::RefractStack,
        TaskId::FresnelSchlick,
        TaskId::CosineSample,
        TaskId::SmithG1,
        TaskId::CookTorrance,
        TaskId::AnisoNdf,
        TaskId::Phong,
        TaskId::KajiyaKay,
        TaskId::BeckmannNdf,
        TaskId::NdfSample,
        TaskId::BrdfCheck,
        TaskId::PathTrace,
        TaskId::Mis,
        TaskId::DeltaTracking,
    ];

    /// The task's row in [`TASKS`].
    pub fn info(self) -> &'static TaskInfo {
        &TASKS[self as usize]
    }

    /// The task's id as written on the command line and in file names (`reflect`, …).
    pub fn name(self) -> &'static str {
        self.info().id
    }

    /// Looks a task up by its id (`"cook_torrance"`) or a unique prefix of it.
    pub fn parse(s: &str) -> Result<TaskId, String> {
        if let Some(t) = TaskId::ALL.iter().find(|t| t.name() == s) {
            return Ok(*t);
        }
        let matches: Vec<TaskId> = TaskId::ALL
            .iter()
            .copied()
            .filter(|t| t.name().starts_with(s))
            .collect();
        match matches.as_slice() {
            [one] => Ok(*one),
            [] => Err(format!(
                "no task `{s}`; the tasks are: {}",
                TaskId::ALL.map(|t| t.name()).join(", ")
            )),
            many => Err(format!(
                "`{s}` could be any of: {}",
                many.iter().map(|t| t.name()).collect::<Vec<_>>().join(", ")
            )),
        }
    }
}

impl std::fmt::Display for TaskId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// One row of the task table.
#[derive(Debug)]
pub struct TaskInfo {
    /// The task's id: its file name in `exercises/` and `solutions/`, and its CLI name.
    pub id: &'static str,
    /// A short title.
    pub title: &'static str,
    /// Where the task comes from in the worksheet (ERRATA.md's section labels).
    pub section: &'static str,
    /// Points the task is worth.
    pub points: u32,
    /// Tasks this one calls through `t: &impl Tasks` (the grader substitutes the reference
    /// for them when grading this task alone).
    pub needs: &'static [TaskId],
    /// Hints in increasing levels of detail; `pbrlab hint TASK` shows them one at a time.
    pub hints: &'static [&'static str],
}

/// The task table, indexed by [`TaskId`].
pub static TASKS: [TaskInfo; 15] = [
    TaskInfo {
        id: "reflect",
        title: "Mirror reflection",
        section: "§1.1, §1.5",
        points: 5,
        needs: &[],
        hints: &[
            "Both wo and the result point away from the surface. Split wo into the part along \
             n and the part in the surface plane; reflection keeps one and flips the other.",
            "The result is 2 (wo·n) n − wo. Check it on wo = (0.6, 0.8, 0), n = (0, 1, 0): you \
             should get (−0.6, 0.8, 0), still above the surface.",
            "The normal you are given may not have unit length. Normalise it first, or the \
             component along n is scaled by |n|².",
            "The worksheet's §1.1 formula wo − 2(wo·n)n is for a direction travelling towards \
             the surface; in our convention (pointing away) it returns a vector below the \
             surface. The two formulas are negatives of each other.",
        ],
    },
    TaskInfo {
        id: "refract_stack",
        title: "Snell's law, total internal reflection, a layer stack",
        section: "§1.2, §1.4",
        points: 10,
        needs: &[TaskId::FresnelSchlick],
        hints: &[
            "Snell's law relates the sines: eta_i sin θi = eta_t sin θt. Work with cosines: \
             cos²θt = 1 − (eta_i/eta_t)² (1 − cos²θi). A negative value means total internal \
             reflection.",
            "Rounding can make 1 − sin²θt slightly negative right at the critical angle; \
             decide TIR with sin²θt ≥ 1 and clamp before the square root. The critical angle \
             only exists when eta_i > eta_t.",
            "For the stack, the product eta sin θ is the same in every medium, so each angle \
             follows from the first one. The shift of the ray through a slab of thickness d is \
             d sin(θ_in − θ_slab) / cos θ_slab; d tan θ_slab is a different quantity (how far \
             the exit point is from the entry point along the interface).",
            "Transmitted intensity multiplies (1 − R) over the interfaces. Use your \
             fresnel_schlick for one column and crate::optics::fresnel_dielectric_f64 for the \
             exact one.",
            "With η = eta_i/eta_t, c = wi·n̂ and cos θt from the clamped square root, the \
             transmitted direction is −η wi + (η c − cos θt) n̂: the tangential part scales \
             by η and flips side, the normal part points into the second medium.",
            "When the stack stops at TIR on interface k: theta has k + 1 entries, the \
             reflectances k + 1 (the last is 1), the per-slab shifts one entry per slab \
             entered, and both transmitted intensities are 0. A ray grazing out of a slab \
             exactly at the critical angle counts as TIR.",
        ],
    },
    TaskInfo {
        id: "fresnel_schlick",
        title: "Fresnel reflectance by Schlick's approximation",
        section: "§1.3, §1.4.4, §3.4.2",
        points: 8,
        needs: &[],
        hints: &[
            "R0 is the reflectance at normal incidence: ((eta_i − eta_t)/(eta_i + eta_t))². \
             Check glass/water: 0.0036085, not the 0.0041 the worksheet prints.",
            "Schlick's curve is R0 + (1 − R0)(1 − cos θ)^5, but which θ? Going from dense to \
             less dense (eta_i > eta_t), use the transmitted angle; if there is none, the \
             reflectance is 1.",
            "When the two indices are equal nothing reflects, at any angle. Make sure your code \
             returns 0 there instead of (1 − cos θ)^5.",
            "Dense to less dense: sin²θt = (eta_i/eta_t)² (1 − cos²θi). If that is ≥ 1, \
             return 1; otherwise use cos θt = sqrt(1 − sin²θt) in Schlick's curve. Clamp the \
             cosine to ≤ 1 so 1 − cos never goes negative.",
        ],
    },
    TaskInfo {
        id: "cosine_sample",
        title: "Cosine-weighted hemisphere sampling",
        section: "§2.7",
        points: 8,
        needs: &[],
        hints: &[
            "The target density is cos θ / π per steradian. Its marginal in θ is \
             2 sin θ cos θ, whose CDF is sin²θ; φ is uniform on [0, 2π).",
            "Inverting gives cos θ = sqrt(1 − u1) (or sqrt(u1): both are uniform). \
             Alternatively, sample a uniform point on the unit disk and lift it to the \
             hemisphere (Malley's method).",
            "The pdf must agree with the directions you produce: cos θ / π above the surface \
             and 0 below it.",
        ],
    },
    TaskInfo {
        id: "smith_g1",
        title: "GGX Smith masking G1",
        section: "§3.2",
        points: 6,
        needs: &[],
        hints: &[
            "G1 = 1 / (1 + Λ), with Λ = (−1 + sqrt(1 + α² tan²θ)) / 2 for GGX.",
            "A direction below the surface is fully masked: return 0 when cos θ ≤ 0 (the \
             worksheet's formula goes negative there).",
            "For tiny α² tan²θ the subtraction −1 + sqrt(1 + a) loses every digit in f32. \
             Rewrite it as a / (1 + sqrt(1 + a)), or use the cosine form \
             2 cos θ / (cos θ + sqrt(α² + (1 − α²) cos²θ)).",
            "Check the limits: α = 0 gives 1 above the horizon (and must not give NaN at the \
             horizon), α = 1 and cos θ = 0.5 give 2/3, and cos θ = 1e-8 with α = 0.5 gives \
             about 4e-8.",
        ],
    },
    TaskInfo {
        id: "cook_torrance",
        title: "Cook-Torrance microfacet BRDF",
        section: "§3.1, §3.3, §3.4",
        points: 10,
        needs: &[TaskId::SmithG1, TaskId::AnisoNdf],
        hints: &[
            "f = F(wo·h) D(h) G1(wo) G1(wi) / (4 cos θo cos θi), with h the normalised sum of \
             wo and wi. F is Schlick's curve with the RGB reflectance f0.",
            "Return 0 when either direction is at or below the horizon; that also guards the \
             division.",
            "Call t.aniso_ndf(h, alpha_x, alpha_y) for D. For G1 with anisotropic roughness, \
             pass the roughness projected onto the direction's azimuth: \
             crate::bsdf::projected_alpha(w, alpha_x, alpha_y).",
            "Fresnel is evaluated at the microfacet: its cosine is wo·h (equal to wi·h), not \
             cos θo. crate::optics::schlick_weight(wo·h) gives (1 − wo·h)^5, and \
             F = f0 + (1 − f0) · that, per channel.",
            "Check: wi = n, α = 0.5, f0 = 0.04, wo at 89.999° from n gives about 0.008570 \
             (with G = 1 it would be 123). And |wo + wi|² can be tiny for nearly opposite \
             directions: return 0 instead of normalising it.",
        ],
    },
    TaskInfo {
        id: "aniso_ndf",
        title: "Anisotropic GGX normal distribution",
        section: "§4.1",
        points: 6,
        needs: &[],
        hints: &[
            "D(h) = 1 / (π αx αy cos⁴θh (1 + tan²θh (cos²φh/αx² + sin²φh/αy²))²).",
            "In Cartesian form this is 1 / (π αx αy (hx²/αx² + hy²/αy² + hz²)²), which needs \
             no trigonometry and stays accurate as α → 0 in f32.",
            "h below the surface (h.z ≤ 0) has density 0, and α = 0 is a delta: raise the \
             roughnesses to crate::bsdf::MIN_ALPHA first.",
            "Check: h = (0.5, 0.5, √2/2) gives 0.2037183 for α = (0.5, 0.5) and 0.0048006 \
             for α = (0.1, 1.0); α = (1, 1) gives 1/π for every h above the surface.",
        ],
    },
    TaskInfo {
        id: "phong",
        title: "Phong BRDF and a reciprocity test",
        section: "§4.2",
        points: 6,
        needs: &[TaskId::Reflect],
        hints: &[
            "The lobe is centred on the mirror of wi; evaluate max(0, r·wo)^n so a negative \
             cosine never reaches powf (a fractional power of a negative number is NaN).",
            "For the test, draw random pairs of directions above the surface and compare \
             f(wi, wo) with f(wo, wi). Report the largest relative difference.",
            "Work out r(wi)·wo on paper: it is symmetric in wi and wo, so the Phong BRDF is \
             reciprocal, whatever the worksheet says. The non-reciprocal model is the old \
             Phong shading formula, whose implied BRDF divides by cos θi.",
        ],
    },
    TaskInfo {
        id: "kajiya_kay",
        title: "Kajiya-Kay hair fibre model",
        section: "§4.3",
        points: 6,
        needs: &[],
        hints: &[
            "Everything depends on the angles to the fibre tangent t: cos θ = t·w and \
             sin θ = sqrt(1 − cos²θ), clamped.",
            "Light leaving a cylinder by mirror reflection lies on a cone: t·wo = −t·wi. The \
             cosine of the angle between wo and that cone is sin θi sin θo − cos θi cos θo.",
            "Diffuse is kd sin θi; specular is ks max(0, cone cosine)^p. The worksheet's \
             variant divides by sin θi sin θo and goes negative; do not use it.",
        ],
    },
    TaskInfo {
        id: "beckmann_ndf",
        title: "Beckmann normal distribution",
        section: "§3.4.3",
        points: 4,
        needs: &[],
        hints: &[
            "D(h) = exp(−tan²θh / α²) / (π α² cos⁴θh) for h above the surface.",
            "At grazing h the exponential wins: return 0 when cos θh ≤ 0 or when cos⁴θh \
             underflows, instead of computing 0 · ∞.",
            "Check with α = 0.1: θh = 0 gives 100/π = 31.8309886; θh = 30° gives \
             1.889056e-13; θh = 42.5° (the half vector for a view at 85°, not 45°) gives \
             3.683271e-35.",
        ],
    },
    TaskInfo {
        id: "ndf_sample",
        title: "Sampling the GGX NDF and the half-vector Jacobian",
        section: "§5.2",
        points: 8,
        needs: &[TaskId::AnisoNdf, TaskId::Reflect],
        hints: &[
            "Two steps: draw a microfacet normal h, then wi = t.reflect(wo, h). D(h) cos θh \
             integrates to 1 over the hemisphere, so it is a density for h: invert its CDF in \
             θh, with φh uniform.",
            "Isotropic GGX inverts to tan θh = α sqrt(u1/(1 − u1)), φh = 2π u2. For αx ≠ αy, \
             build the normal for α = 1, scale its x by αx and its y by αy, and normalise.",
            "The density of wi is the density of h times |dωh/dωi| = 1/(4 |wo·h|).",
            "Reject (None / pdf 0) when wo·h ≤ 0 or when wi ends up below the surface; \
             ndf_pdf must be 0 for every wi the sampler cannot return.",
        ],
    },
    TaskInfo {
        id: "brdf_check",
        title: "BRDF plausibility checker",
        section: "§2.2, §2.6",
        points: 6,
        needs: &[TaskId::Phong],
        hints: &[
            "Three numbers: the smallest value, the worst relative asymmetry f(wi,wo) vs \
             f(wo,wi) (t.reciprocity_gap does that part), and the largest directional albedo.",
            "Estimate the albedo of a fixed wi by Monte Carlo over wo: mean of f cos θo / pdf \
             with uniform hemisphere samples (crate::sampling::uniform_hemisphere).",
            "Test incident directions near grazing too: that is where the worksheet's custom \
             BRDF breaks energy conservation.",
            "f32::min and f32::max ignore NaN. A BRDF that returns NaN must come out \
             implausible, so let a NaN value win when you take the minimum and the maximum.",
        ],
    },
    TaskInfo {
        id: "path_trace",
        title: "Path tracing with next-event estimation and Russian roulette",
        section: "§5.3",
        points: 15,
        needs: &[TaskId::Mis],
        hints: &[
            "Return 0 when depth <= 0. Otherwise start from the light at the end of the \
             segment: scene.emitted(hit, -ray.dir), or scene.environment(ray.dir) if the ray \
             escaped, but only when segment.emission_counted is false (camera rays). A \
             segment that mis sampled has its light counted already, with its MIS weight.",
            "With depth == 1 nothing more may be added. Otherwise call t.mis(scene, hit, wo, \
             scene.heuristic(), sampler): its radiance is the direct light, and its bounce \
             (if any) is the traced continuation. Add bounce.weight times the radiance that \
             t.path_trace returns for bounce.segment with depth − 1.",
            "Russian roulette: when scene.settings().roulette_applies(depth), keep the path \
             with a probability q (for example min(largest component of bounce.weight, \
             0.95)) and divide what it brings back by q. Without the division the image \
             gets darker; without roulette unbounded paths never end.",
            "The worksheet's version returns 0 for every path: it never adds emission or \
             direct light at any level. And with depth starting at 0 its `depth == 0` test \
             never fires; test `depth <= 0`.",
        ],
    },
    TaskInfo {
        id: "mis",
        title: "Direct lighting by multiple importance sampling",
        section: "§5.4",
        points: 15,
        needs: &[],
        hints: &[
            "Two samples, each weighted: a light sample (scene.sample_light) and a BSDF \
             sample (scene.bsdf(hit).sample). Both pdfs in a weight must be per unit solid \
             angle. For an area light, pdf_ω = pdf_area · d² / cos θl with cos θl = \
             n·(x − p)/d at the light; the worksheet leaves cos θl out (33 % too bright in \
             its test scene) and mixes area and solid-angle densities in its weights.",
            "Shadow rays: (ray, t_max) = hit.spawn_to(p), then the light counts when \
             !scene.occluded(&ray, t_max). The worksheet's distance comparison is inverted: \
             blockers nearer than the light never cast a shadow.",
            "The BSDF sample: trace hit.spawn(wi) with scene.intersect. If it hits an emitter \
             (scene.emitted towards −wi, pdf from scene.light_pdf converted with the hit's \
             distance and cosine) or escapes (scene.environment, scene.environment_pdf), add \
             its light times sample.weight times its MIS weight. Return it as the bounce.",
            "Weights: Balance p_a/(p_a + p_b); Power p_a²/(p_a² + p_b²); Bsdf and Light give 1 \
             to the named strategy and 0 to the other (then skip that sample's shadow ray). \
             A delta BSDF sample or a point light has weight 1 always; a pdf sum of 0 means \
             a contribution of 0, not NaN.",
        ],
    },
    TaskInfo {
        id: "delta_tracking",
        title: "Delta tracking in a heterogeneous medium",
        section: "§6.3",
        points: 12,
        needs: &[],
        hints: &[
            "Walk tentative collisions: t += −ln(1 − u) / σ̄ with σ̄ = medium.majorant() and \
             a fresh u at every step. Once t ≥ t_max the path has escaped.",
            "At a tentative collision draw a fresh ξ and compare ξ σ̄ with the coefficients at \
             ray.at(t): below σa it is an absorption, below σa + σs a scattering, otherwise a \
             null collision and the walk goes on.",
            "The worksheet reuses u[0] and u[1] at every step: in a homogeneous medium with \
             σ̄ = 2σt it lets 57 % of paths through where e^−1 = 37 % is right. It also \
             reports escapes as absorptions, and loops forever when σ̄ = 0 and u = 0.",
            "Guard σ̄ ≤ 0 (or NaN): nothing can collide, so the path escapes. Stop with \
             FreeFlight::Exhausted after max_steps tentative collisions.",
        ],
    },
];
