//! Sets of tasks: which tasks a mixed implementation takes from the student, and which
//! tasks a scene needs.

use crate::task::TaskId;

/// A set of tasks, as a bit mask over [`TaskId`]. Used to say which tasks run the student's
/// code in a mixed implementation (the grader's `implementation::mixed`), and which tasks a scene needs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct TaskSet(u32);

impl TaskSet {
    /// The empty set.
    pub const EMPTY: TaskSet = TaskSet(0);

    /// Every task of the worksheet.
    pub fn all() -> Self {
        TaskId::ALL.iter().copied().collect()
    }

    /// True when `task` is in the set.
    pub fn contains(self, task: TaskId) -> bool {
        self.0 & (1 << task as u32) != 0
    }

    /// Adds `task` to the set.
    pub fn insert(&mut self, task: TaskId) {
        self.0 |= 1 << task as u32;
    }

    /// The union of two sets.
    pub fn union(self, other: TaskSet) -> TaskSet {
        TaskSet(self.0 | other.0)
    }

    /// True when the set is empty.
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The tasks in the set, in worksheet order.
    pub fn iter(self) -> impl Iterator<Item = TaskId> {
        TaskId::ALL.into_iter().filter(move |t| self.contains(*t))
    }
}

impl FromIterator<TaskId> for TaskSet {
    fn from_iter<I: IntoIterator<Item = TaskId>>(iter: I) -> Self {
        let mut set = TaskSet::EMPTY;
        for t in iter {
            set.insert(t);
        }
        set
    }
}
