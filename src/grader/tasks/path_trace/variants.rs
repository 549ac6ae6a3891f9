// The variants of `path_trace` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Patch, Variant, variant};
use crate::support::variants::Naive;
use glam::Vec3;
use pbrlab::integrator::Segment;
use pbrlab::sampling::Sampler;
use pbrlab::scene::Scene;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::{TaskId, Tasks};

/// A wrong `path_trace`: the reference's algorithm with one flaw (a task function is a plain
/// `fn`, which cannot capture the flaw, hence a macro).
macro_rules! flawed {
    ($name:expr, $flaw:ident) => {
        variant($name, TaskId::PathTrace, |p| {
            p.path_trace = Some(|t, s, seg, d, sa| path_variant(t, s, seg, d, sa, PathFlaw::$flaw))
        })
    };
}

/// Known-wrong implementations of `path_trace`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    vec![
        flawed!(
            "the sheet's recursion: no light after the camera hit",
            NoLightAfterCamera
        ),
        flawed!(
            "Russian roulette without dividing by q",
            RouletteWithoutDivision
        ),
        flawed!("emission counted twice", EmissionTwice),
        flawed!("the sky added again after an escape", SkyTwice),
        flawed!("a survival probability not capped at 1", UncappedSurvival),
        flawed!("the roulette test inverted", InvertedRoulette),
        flawed!("`depth == 0` as the only stop", OnlyDepthZeroStops),
        flawed!(
            "survival from the smallest channel",
            SurvivalFromSmallestChannel
        ),
        flawed!("a scalar throughput", ScalarThroughput),
        flawed!("black where mis gives no bounce", BlackWithoutBounce),
        flawed!(
            "a path ended where its bounce's weight is below 0.01",
            CutBelowWeight
        ),
    ]
}

/// Correct implementations of `path_trace` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
            "a path traced in a loop, roulette on the path throughput (q capped at 1)",
            PathTrace,
            |p| {
                p.path_trace = Some(|t, scene, segment, depth, sampler| {
                    let (mut segment, mut depth) = (*segment, depth);
                    let (mut radiance, mut beta) = (Vec3::ZERO, Vec3::ONE);
                    while depth > 0 {
                        let counted = segment.emission_counted;
                        let Some(hit) = segment.hit else {
                            if !counted {
                                radiance += beta * scene.environment(segment.ray.dir);
                            }
                            break;
                        };
                        let wo = -segment.ray.dir;
                        if !counted {
                            radiance += beta * scene.emitted(&hit, wo);
                        }
                        if depth == 1 {
                            break;
                        }
                        let direct = t.mis(scene, &hit, wo, scene.heuristic(), sampler);
                        radiance += beta * direct.radiance;
                        let Some(bounce) = direct.bounce else {
                            break;
                        };
                        if depth == 2 {
                            break;
                        }
                        beta *= bounce.weight;
                        if scene.settings().roulette_applies(depth) {
                            let q = beta.max_element().min(1.0);
                            if q.is_nan() || q <= 0.0 || sampler.next_1d() >= q {
                                break;
                            }
                            beta /= q;
                        }
                        segment = bounce.segment;
                        depth -= 1;
                    }
                    radiance
                })
            },
        ),
        variant(
            "roulette with a fixed q = 0.9 before the direct light, dividing both",
            PathTrace,
            |p| p.path_trace = Some(roulette_first),
        ),
    ]
}

/// Naive implementations of `path_trace` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`path_trace` has no test for depth ≤ 0",
        PathTrace,
        |p| {
            p.path_trace = Some(textbook::path_trace_no_depth_guard);
        },
        vec![("path_trace/depth_zero", WrongValue)],
    )]
}

/// How a `path_trace` variant goes wrong.
#[derive(Clone, Copy, PartialEq)]
enum PathFlaw {
    /// The sheet: the recursion never adds emission or direct light after the camera hit.
    NoLightAfterCamera,
    /// Russian roulette that forgets to divide by the survival probability.
    RouletteWithoutDivision,
    /// Emission added again where `mis` already counted it.
    EmissionTwice,
    /// The sky added again when a bounce escapes, though `mis` already counted it.
    SkyTwice,
    /// A survival probability not capped at 1 (`q = max(weight)`): a bounce weight above 1
    /// always survives and is still divided by q.
    UncappedSurvival,
    /// The roulette test inverted: the path ends with probability q instead of 1 − q.
    InvertedRoulette,
    /// The sheet's `depth == 0` test: a depth below 0 goes on.
    OnlyDepthZeroStops,
    /// A survival probability from the smallest channel of the weight: a channel that
    /// reflects nothing ends every path.
    SurvivalFromSmallestChannel,
    /// The throughput kept as one number (the weight's largest channel).
    ScalarThroughput,
    /// Black returned when `mis` gives no bounce, losing the light gathered so far.
    BlackWithoutBounce,
    /// A path ended, without roulette's compensation, where the bounce's weight falls
    /// below 0.01: light that arrives through a dark bounce is lost.
    CutBelowWeight,
}

fn path_variant(
    t: &Patch,
    scene: &Scene,
    segment: &Segment,
    depth: i32,
    sampler: &mut Sampler,
    flaw: PathFlaw,
) -> Vec3 {
    if depth <= 0 && !(flaw == PathFlaw::OnlyDepthZeroStops && depth < 0) {
        return Vec3::ZERO;
    }
    let counted = segment.emission_counted && flaw != PathFlaw::EmissionTwice;
    let Some(hit) = &segment.hit else {
        return if counted && flaw != PathFlaw::SkyTwice {
            Vec3::ZERO
        } else {
            scene.environment(segment.ray.dir)
        };
    };
    let wo = -segment.ray.dir;
    let mut radiance = if counted {
        Vec3::ZERO
    } else {
        scene.emitted(hit, wo)
    };
    if depth == 1 {
        return radiance;
    }
    let direct = t.mis(scene, hit, wo, scene.heuristic(), sampler);
    if flaw != PathFlaw::NoLightAfterCamera {
        radiance += direct.radiance;
    }
    let Some(bounce) = direct.bounce else {
        return if flaw == PathFlaw::BlackWithoutBounce {
            Vec3::ZERO
        } else {
            radiance
        };
    };
    if depth == 2 {
        return radiance;
    }
    let mut weight = if flaw == PathFlaw::ScalarThroughput {
        Vec3::splat(bounce.weight.max_element())
    } else {
        bounce.weight
    };
    if flaw == PathFlaw::CutBelowWeight && weight.max_element() < 0.01 {
        return radiance;
    }
    if scene.settings().roulette_applies(depth) {
        let q = match flaw {
            PathFlaw::UncappedSurvival => weight.max_element(),
            PathFlaw::SurvivalFromSmallestChannel => weight.min_element().min(0.95),
            _ => weight.max_element().min(0.95),
        };
        let u = sampler.next_1d();
        let ends = match flaw {
            PathFlaw::InvertedRoulette => u < q,
            _ => u >= q,
        };
        if q <= 0.0 || ends {
            return radiance;
        }
        if flaw != PathFlaw::RouletteWithoutDivision {
            weight /= q;
        }
    }
    let further = t.path_trace(scene, &bounce.segment, depth - 1, sampler);
    radiance
        + weight
            * if flaw == PathFlaw::NoLightAfterCamera {
                Vec3::ZERO
            } else {
                further
            }
}

/// `path_trace` with Russian roulette at the start of a step (from depth 3 on), with a fixed
/// survival probability, dividing the direct light and the continuation alike.
fn roulette_first(
    t: &Patch,
    scene: &Scene,
    segment: &Segment,
    depth: i32,
    sampler: &mut Sampler,
) -> Vec3 {
    const Q: f32 = 0.9;
    if depth <= 0 {
        return Vec3::ZERO;
    }
    let Some(hit) = &segment.hit else {
        return if segment.emission_counted {
            Vec3::ZERO
        } else {
            scene.environment(segment.ray.dir)
        };
    };
    let wo = -segment.ray.dir;
    let emitted = if segment.emission_counted {
        Vec3::ZERO
    } else {
        scene.emitted(hit, wo)
    };
    if depth == 1 {
        return emitted;
    }
    let mut scale = 1.0;
    if depth >= 3 && scene.settings().roulette_applies(depth) {
        if sampler.next_1d() >= Q {
            return emitted;
        }
        scale = 1.0 / Q;
    }
    let direct = t.mis(scene, hit, wo, scene.heuristic(), sampler);
    let mut rest = direct.radiance;
    if depth >= 3
        && let Some(b) = &direct.bounce
    {
        rest += b.weight * t.path_trace(scene, &b.segment, depth - 1, sampler);
    }
    emitted + rest * scale
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// A path tracer that stops only at depth 1 (no test for depth ≤ 0), so a path started at
    /// depth 0 runs on until Russian roulette ends it.
    pub fn path_trace_no_depth_guard(
        t: &impl Tasks,
        scene: &Scene,
        segment: &Segment,
        depth: i32,
        sampler: &mut Sampler,
    ) -> Vec3 {
        let Some(hit) = &segment.hit else {
            return if segment.emission_counted {
                Vec3::ZERO
            } else {
                scene.environment(segment.ray.dir)
            };
        };
        let wo = -segment.ray.dir;
        let mut radiance = if segment.emission_counted {
            Vec3::ZERO
        } else {
            scene.emitted(hit, wo)
        };
        if depth == 1 {
            return radiance;
        }
        let direct = t.mis(scene, hit, wo, scene.heuristic(), sampler);
        radiance += direct.radiance;
        let Some(bounce) = direct.bounce else {
            return radiance;
        };
        let mut weight = bounce.weight;
        if scene.settings().roulette_applies(depth) {
            let q = weight.max_element().min(0.95);
            if sampler.next_1d() >= q {
                return radiance;
            }
            weight /= q;
        }
        radiance + weight * t.path_trace(scene, &bounce.segment, depth - 1, sampler)
    }
}
