//! When a scene's render check counts: a scene's points are awarded once every task it
//! needs has passed, so a render that looks right by accident (or because the reference
//! stood in) does not earn points for tasks that fail on their own.

use super::verdict::{TaskOutcome, TaskStatus};
use crate::task_set::TaskSet;
use crate::worksheet::TaskId;

/// The tasks of `needs` that have not passed in `graded` (a task that was not graded counts
/// as not passed; one that is [`TaskStatus::Partial`] counts as passed). Empty when the
/// scene's render check may be awarded.
pub fn missing_tasks(needs: TaskSet, graded: &[TaskOutcome]) -> Vec<TaskId> {
    needs
        .iter()
        .filter(|task| {
            !graded.iter().any(|t| {
                t.task == task.name()
                    && matches!(t.status, TaskStatus::Passed | TaskStatus::Partial)
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(task: TaskId, status: TaskStatus) -> TaskOutcome {
        TaskOutcome {
            task: task.name().into(),
            status,
            points: 0.0,
            max_points: 1.0,
            checks: Vec::new(),
            output: String::new(),
            seconds: 0.0,
        }
    }

    #[test]
    fn a_scene_waits_for_every_task_it_needs() {
        let needs: TaskSet = [TaskId::CosineSample, TaskId::CookTorrance]
            .into_iter()
            .collect();
        let graded = [
            outcome(TaskId::CosineSample, TaskStatus::Passed),
            outcome(TaskId::CookTorrance, TaskStatus::Failed),
        ];
        assert_eq!(missing_tasks(needs, &graded), vec![TaskId::CookTorrance]);
        assert_eq!(
            missing_tasks(needs, &graded[..1]),
            vec![TaskId::CookTorrance]
        );
        let all = [
            graded[0].clone(),
            outcome(TaskId::CookTorrance, TaskStatus::Partial),
        ];
        assert!(missing_tasks(needs, &all).is_empty());
    }
}
