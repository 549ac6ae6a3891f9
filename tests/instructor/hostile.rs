//! Hostile student code at run time: a `smith_g1` that computes the right values but first
//! tries to cheat or to break out of its worker. Every attempt must fail inside the sandbox
//! (the attack prints `SANDBOX BREACH` when one succeeds), the task must be graded as the
//! honest code it otherwise is, and the other tasks must not notice.
//!
//! The workers are this test binary (`worker_entry`), started by the real grader, so the
//! real sandbox (`pbrlab::grade::sandbox`) and the real pipes are exercised. What is refused
//! at compile time (naming the reference, `#[path]`, `include_str!`, `unsafe`, …) is tested
//! in `tests/instructor/trust.rs`.

use crate::support::patch::Patch;
use pbrlab::grade::isolation::Launcher;
use pbrlab::grade::runner::{GradeOptions, grade};
use pbrlab::grade::verdict::{GradeReport, TaskStatus};
use pbrlab::implementation::ImplChoice;
use pbrlab::worksheet::TaskId;
use std::io::Write;
use std::path::PathBuf;
use std::sync::Once;
use std::time::Duration;

const ATTACK: &str = "PBRLAB_TEST_ATTACK";
const CANARY: &str = "PBRLAB_TEST_CANARY";
const BREACH: &str = "SANDBOX BREACH";
const LEAK: &str = "LEAKED INPUT";

fn breach(what: impl std::fmt::Display) {
    println!("{BREACH}: {what}");
}

/// Files a cheater would like to read: the stored expected data, the reference's source, the
/// grader's binary and this process's own memory (where the job's nonce lives).
fn read_answers() {
    let root = pbrlab::repository_root();
    for file in [
        root.join("src/grader/tasks/smith_g1/expected.snap"),
        root.join("solutions/smith_g1.rs"),
        root.join("Cargo.toml"),
        PathBuf::from("/proc/self/exe"),
        PathBuf::from("/proc/self/mem"),
        PathBuf::from("/proc/self/environ"),
        PathBuf::from("/etc/passwd"),
    ] {
        if std::fs::File::open(&file).is_ok() {
            breach(format!("opened {}", file.display()));
        }
    }
    if std::fs::read_dir(root).is_ok() {
        breach("listed the repository");
    }
}

/// Files a cheater would like to write: the report, the binary, the scenes, the stored
/// data; a canary file outside the worker's directory stands in for the report.
fn write_outside() {
    let root = pbrlab::repository_root();
    let canary = PathBuf::from(std::env::var(CANARY).unwrap_or_default());
    if std::fs::write(&canary, "forged report").is_ok() {
        breach(format!("overwrote {}", canary.display()));
    }
    if std::fs::remove_file(&canary).is_ok() {
        breach(format!("removed {}", canary.display()));
    }
    let new_files = [
        canary.with_extension("new"),
        root.join("scenes/breach.yaml"),
        root.join("src/grader/tasks/smith_g1/breach.snap"),
        std::env::current_exe()
            .unwrap_or_default()
            .with_file_name("breach"),
    ];
    for file in new_files {
        if std::fs::write(&file, "x").is_ok() {
            let _ = std::fs::remove_file(&file);
            breach(format!("created {}", file.display()));
        }
    }
    if std::fs::OpenOptions::new()
        .append(true)
        .open(root.join("scenes/cornell.yaml"))
        .is_ok()
    {
        breach("opened scenes/cornell.yaml for writing");
    }
    // Its own directory is writable: scratch files are allowed.
    let own = std::env::temp_dir().join("scratch.txt");
    if std::fs::write(&own, "allowed").is_err() {
        println!("could not write {} (it should be writable)", own.display());
    }
}

/// A process that outlives the grade, or holds the grader's pipes open.
fn spawn_daemon() {
    for program in ["/bin/sleep", "/usr/bin/sleep", "/bin/sh"] {
        if let Ok(mut child) = std::process::Command::new(program).arg("1000").spawn() {
            let _ = child.kill();
            breach(format!("started {program}"));
        }
    }
    let thread = std::thread::spawn(|| 1 + 1).join();
    if !matches!(thread, Ok(2)) {
        println!("could not start a thread (threads should work)");
    }
}

/// The network, in and out, and local sockets.
fn open_sockets() {
    if std::net::TcpListener::bind("127.0.0.1:0").is_ok() {
        breach("listened on TCP");
    }
    if std::net::TcpStream::connect_timeout(
        &"127.0.0.1:9".parse().expect("an address"),
        Duration::from_millis(200),
    )
    .is_ok()
    {
        breach("connected over TCP");
    }
    if std::net::UdpSocket::bind("127.0.0.1:0").is_ok() {
        breach("bound a UDP socket");
    }
    if std::os::unix::net::UnixStream::pair().is_ok() {
        breach("made a UNIX socket pair");
    }
}

/// New machine code: what loading a library (the handout's compiled reference, carried in
/// a submission) or generated code needs, an executable mapping or an executable page.
fn load_code() {
    let page = 4096;
    // SAFETY: plain system calls on memory this function owns; nothing is executed.
    unsafe {
        let mapped = libc::mmap(
            std::ptr::null_mut(),
            page,
            libc::PROT_READ | libc::PROT_EXEC,
            libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
            -1,
            0,
        );
        if mapped != libc::MAP_FAILED {
            breach("mapped executable memory");
        }
        let writable = libc::mmap(
            std::ptr::null_mut(),
            page,
            libc::PROT_READ | libc::PROT_WRITE,
            libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
            -1,
            0,
        );
        if writable == libc::MAP_FAILED {
            println!("could not map writable memory (it should work)");
        } else if libc::mprotect(writable, page, libc::PROT_READ | libc::PROT_EXEC) == 0 {
            breach("made a page executable");
        }
    }
}

/// The grader's environment (under `cargo test`: PATH, HOME, every CARGO_ variable; in a
/// package, its settings): none of it may reach the worker, which gets only what the
/// launcher sets.
fn read_environment() {
    const SET_BY_THE_GRADER: [&str; 6] = [
        "CI",
        "RAYON_NUM_THREADS",
        "MALLOC_ARENA_MAX",
        "TMPDIR",
        ATTACK,
        CANARY,
    ];
    for (key, _) in std::env::vars_os() {
        let key = key.to_string_lossy();
        if !SET_BY_THE_GRADER.contains(&key.as_ref()) {
            breach(format!("read the grader's environment variable {key}"));
        }
    }
}

/// Output that used to break the grader: invalid UTF-8, and one line of 200 MB.
fn garble_output() {
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(b"\xff\xfe not UTF-8 \xc3\x28\n");
    let chunk = vec![b'x'; 1 << 20];
    for _ in 0..200 {
        let _ = out.write_all(&chunk);
    }
    let _ = out.write_all(b"\n");
    let _ = out.flush();
}

/// A cheater that somehow knows the job's nonce (the student's code cannot read it) and
/// sends a result of its own: no outputs at all, so that no check could fail. The grader's
/// list of checks is its own, so every check fails for want of an output.
fn forge_with_the_nonce() -> ! {
    use pbrlab::grade::worker::{Delivery, RESULT_MARKER, Record};
    let delivery: Delivery =
        serde_json::from_reader(std::io::stdin()).expect("the job arrives on stdin");
    let nonce = delivery.job.nonce;
    let empty = serde_json::to_string(&Record::Outputs { raw: Vec::new() }).expect("json");
    println!("\nPBRLAB-STARTED {nonce} {{}}\n{RESULT_MARKER} {nonce} {empty}");
    std::process::exit(0)
}

/// The worker: runs only when started by the tests below. Each attack runs once, at the
/// first call of `smith_g1`; the function itself is the reference's.
#[test]
fn worker_entry() {
    let Ok(name) = std::env::var(ATTACK) else {
        return;
    };
    crate::support::install();
    if name == "forge" {
        forge_with_the_nonce();
    }
    if name == "leak" {
        // Prints every input it is given and panics on the last case it sees, its input
        // in the message: all of it must stay out of what the student sees of hidden cases.
        let mut patch = Patch::new(TaskId::SmithG1);
        patch.smith_g1 = Some(|w, alpha| {
            println!("{LEAK} {}", alpha.to_bits());
            assert!(alpha.to_bits() % 2 == 0, "{LEAK} {}", alpha.to_bits());
            pbrlab_solutions::smith_g1::smith_g1(w, alpha)
        });
        pbrlab::grade::worker::serve(|spec, _| Ok(patch.only(spec.student_tasks())))
    }
    static ONCE: Once = Once::new();
    let mut patch = Patch::new(TaskId::SmithG1);
    patch.misbehave = Some(match name.as_str() {
        "read" => || ONCE.call_once(read_answers),
        "write" => || ONCE.call_once(write_outside),
        "spawn" => || ONCE.call_once(spawn_daemon),
        "sockets" => || ONCE.call_once(open_sockets),
        "output" => || ONCE.call_once(garble_output),
        "environment" => || ONCE.call_once(read_environment),
        "threads" => || ONCE.call_once(flood_threads),
        "disk" => || ONCE.call_once(flood_disk),
        "load" => || ONCE.call_once(load_code),
        other => panic!("unknown attack {other}"),
    });
    pbrlab::grade::worker::serve(|spec, _| Ok(patch.only(spec.student_tasks())))
}

/// Grades reflect, smith_g1 and cook_torrance with workers that attack with `attack`.
fn grade_under(attack: &str, canary: &std::path::Path) -> GradeReport {
    crate::support::install();
    let launcher = Launcher {
        program: std::env::current_exe().expect("test binary path"),
        args: [
            "--exact",
            "hostile::worker_entry",
            "--nocapture",
            "--test-threads=1",
        ]
        .map(String::from)
        .to_vec(),
        env: vec![
            (ATTACK.into(), attack.into()),
            (CANARY.into(), canary.display().to_string()),
        ],
    };
    let options = GradeOptions {
        tasks: vec![TaskId::Reflect, TaskId::SmithG1, TaskId::CookTorrance],
        implementation: ImplChoice::Student,
        timeout: Duration::from_secs(20),
        renders: false,
        ..GradeOptions::default()
    };
    grade(&options, &launcher).expect("grading runs")
}

/// Runs `attack` and checks that it achieved nothing: every task passes as honest code,
/// no output reports a breach, the canary is intact, and the sandbox was fully in force.
fn attack_fails(attack: &str) -> GradeReport {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let canary = dir.path().join("results.json");
    std::fs::write(&canary, "genuine").expect("canary written");
    let report = grade_under(attack, &canary);
    for t in &report.tasks {
        assert_eq!(
            t.status,
            TaskStatus::Passed,
            "{attack}: {} {:?}",
            t.task,
            t.status
        );
        assert!(!t.output.contains(BREACH), "{attack}: {}", t.output);
        assert!(!t.output.contains("should"), "{attack}: {}", t.output);
    }
    assert_eq!(
        std::fs::read_to_string(&canary).expect("canary still there"),
        "genuine"
    );
    let limits = if own_user() {
        // Workers run as a user of their own, so the thread limit binds them.
        "limits in force".to_string()
    } else {
        format!(
            "limits partly: {}",
            pbrlab::grade::isolation::NO_THREAD_LIMIT
        )
    };
    assert_eq!(
        report.sandbox,
        [format!("landlock in force; seccomp in force; {limits}")],
        "{attack}"
    );
    report
}

/// True when the workers (this test binary) run as a user of their own.
fn own_user() -> bool {
    std::env::current_exe().is_ok_and(|exe| pbrlab::grade::isolation::runs_as_own_user(&exe))
}

/// Starts as many threads as it can (3,000 took 0.4 s before workers had a user of their
/// own: the kernel's thread limit does not bind root).
fn flood_threads() {
    let mut started = Vec::new();
    for _ in 0..1000 {
        match std::thread::Builder::new()
            .stack_size(64 << 10)
            .spawn(|| std::thread::sleep(Duration::from_millis(300)))
        {
            Ok(handle) => started.push(handle),
            Err(_) => break,
        }
    }
    let count = started.len();
    for handle in started {
        let _ = handle.join();
    }
    // The limit is in force when the grader gave the worker a user of its own.
    use std::os::unix::fs::MetadataExt;
    let own_user = std::fs::metadata("/proc/self").is_ok_and(|m| m.uid() >= 0x5000_0000);
    if count == 1000 && own_user {
        breach(format!("started {count} threads"));
    }
}

#[test]
fn expected_data_the_reference_and_memory_cannot_be_read() {
    attack_fails("read");
}

#[test]
fn nothing_outside_the_workers_directory_can_be_written() {
    attack_fails("write");
}

#[test]
fn no_process_can_be_started_to_outlive_the_grade_or_hold_its_pipes() {
    attack_fails("spawn");
}

#[test]
fn no_socket_can_be_opened() {
    attack_fails("sockets");
}

#[test]
fn no_library_or_generated_code_can_be_loaded() {
    attack_fails("load");
}

#[test]
fn what_code_prints_of_its_inputs_never_shows_a_hidden_one() {
    use pbrlab::grade::call::Call;
    use pbrlab::grade::value_cases::hidden_inputs;
    crate::support::install();
    let seed = 4242;
    let launcher = Launcher {
        program: std::env::current_exe().expect("test binary path"),
        args: [
            "--exact",
            "hostile::worker_entry",
            "--nocapture",
            "--test-threads=1",
        ]
        .map(String::from)
        .to_vec(),
        env: vec![(ATTACK.into(), "leak".into())],
    };
    let options = GradeOptions {
        tasks: vec![TaskId::SmithG1],
        implementation: ImplChoice::Student,
        timeout: Duration::from_secs(20),
        renders: false,
        hidden_seed: Some(seed),
        ..GradeOptions::default()
    };
    let report = grade(&options, &launcher).expect("grading runs");
    let g1 = report.task("smith_g1").expect("graded");
    assert!(
        g1.output.contains(LEAK),
        "what the visible checks' worker printed is shown: {}",
        g1.output
    );
    // What a student sees: the text report (hidden checks by count), the task's output and
    // status, and the visible tests of the Gradescope results.
    let gradescope = serde_json::to_value(pbrlab::grade::report::gradescope(&report)).unwrap();
    let shown: Vec<String> = gradescope["tests"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|t| t["visibility"] == "visible")
        .map(|t| t.to_string())
        .collect();
    let visible = format!(
        "{}\n{}\n{:?}\n{}",
        pbrlab::grade::report::text(&report, pbrlab::grade::report::Detail::Verbose),
        g1.output,
        g1.status,
        shown.join("\n")
    );
    let leak = |call: &Call| match call {
        Call::smith_g1 { alpha, .. } => Some(format!("{LEAK} {}", alpha.to_bits())),
        _ => None,
    };
    // The attack prints α alone: a hidden case shares its α with a public one now and then
    // (α = 0 and 1 are declared special values), and the public one may be shown.
    let public: Vec<String> = pbrlab::grade::value_cases::public_inputs(TaskId::SmithG1)
        .iter()
        .filter_map(|case| leak(&case.call))
        .collect();
    let hidden: Vec<String> = hidden_inputs(TaskId::SmithG1, seed)
        .iter()
        .filter_map(|case| leak(&case.call))
        .filter(|line| !public.contains(line))
        .collect();
    assert!(!hidden.is_empty());
    for line in &hidden {
        assert!(
            !visible.contains(line.as_str()),
            "{line} reached the report"
        );
    }
}

/// Fills the worker's temporary folder (its working directory) with 2 GiB, in files each
/// under the kernel's file-size limit.
fn flood_disk() {
    let chunk = vec![7u8; 1 << 20];
    for file in 0..20 {
        let Ok(mut out) = std::fs::File::create(format!("flood-{file}")) else {
            return;
        };
        for _ in 0..100 {
            if out.write_all(&chunk).is_err() {
                return;
            }
        }
    }
    breach("wrote 2 GiB into the temporary folder");
}

#[test]
fn a_disk_flood_costs_its_own_task_only() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let report = grade_under("disk", &dir.path().join("canary"));
    for t in &report.tasks {
        if t.task == "smith_g1" {
            assert!(
                matches!(&t.status, TaskStatus::Crashed { reason } if reason.contains("temporary folder")),
                "{:?}",
                t.status
            );
        } else {
            assert_eq!(t.status, TaskStatus::Passed, "{}: {:?}", t.task, t.status);
        }
        assert!(!t.output.contains(BREACH), "{}", t.output);
    }
}

#[test]
fn a_thread_flood_stops_at_the_workers_limit() {
    attack_fails("threads");
}

#[test]
fn the_graders_environment_does_not_reach_the_worker() {
    attack_fails("environment");
}

#[test]
fn invalid_utf8_and_a_huge_line_are_only_output() {
    let report = attack_fails("output");
    let g1 = report.task("smith_g1").expect("graded");
    assert!(g1.output.contains("not UTF-8"), "{}", g1.output);
    assert!(g1.output.len() <= 64 * 1024, "{}", g1.output.len());
}

#[test]
fn a_result_without_outputs_fails_every_check_even_with_the_nonce() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let report = grade_under("forge", &dir.path().join("unused"));
    assert_eq!(report.tasks.len(), 3);
    for t in &report.tasks {
        assert_eq!(t.status, TaskStatus::Failed, "{} {:?}", t.task, t.status);
        assert_eq!(t.points, 0.0, "{}", t.task);
        assert!(!t.checks.is_empty(), "{}", t.task);
        for c in &t.checks {
            assert!(!c.passed, "{}: {} passed", t.task, c.name);
            assert!(
                c.failures
                    .iter()
                    .any(|f| f.contains("no output came back") || f.contains("no value came back")),
                "{}: {:?}",
                t.task,
                c.failures
            );
        }
    }
}

/// Pieces of every stored expected-data file (`src/grader/tasks/<task>/expected.snap`) and
/// reference render (`src/grader/renders/`): the middle 64 bytes.
fn stored_answers() -> Vec<(String, Vec<u8>)> {
    let root = pbrlab::repository_root();
    let expected = std::fs::read_dir(root.join("src/grader/tasks"))
        .expect("the tasks' folders")
        .flatten()
        .map(|task| task.path().join("expected.snap"))
        .filter(|file| file.is_file());
    let renders = std::fs::read_dir(root.join("src/grader/renders"))
        .expect("stored renders")
        .flatten()
        .map(|entry| entry.path());
    let all: Vec<_> = expected.chain(renders).collect();
    assert!(all.len() > 10, "too few stored files: {all:?}");
    all.into_iter()
        .map(|path| {
            let bytes = std::fs::read(&path).expect("readable");
            let middle = bytes.len() / 2;
            let piece = bytes[middle..(middle + 64).min(bytes.len())].to_vec();
            (path.display().to_string(), piece)
        })
        .collect()
}

fn contains(haystack: &[u8], needle: &[u8]) -> bool {
    haystack.windows(needle.len()).any(|w| w == needle)
}

#[test]
fn the_worker_binary_holds_no_expected_data_or_reference_render() {
    let answers = stored_answers();
    assert!(answers.len() >= 10, "{} stored files", answers.len());
    let grader = std::fs::read(crate::support::commands()).expect("the grader's binary");
    let worker = std::fs::read(crate::support::worker()).expect("the worker's binary");
    for (file, piece) in &answers {
        // The grader embeds them (so this search finds what it looks for) ...
        assert!(
            contains(&grader, piece),
            "{file} is not in the grader's binary"
        );
        // ... the process that runs student code does not.
        assert!(
            !contains(&worker, piece),
            "{file} is in the worker's binary"
        );
    }
}

#[test]
fn only_the_worker_binaries_link_the_student_crate() {
    let commands = crate::support::commands();
    let grader = std::fs::read(&commands).expect("the grader's binary");
    let front = std::fs::read(env!("CARGO_BIN_EXE_pbrlab")).expect("the pbrlab binary");
    let built = pbrlab::cli::rebuild::ensure_student_binaries_beside(&commands)
        .expect("the worker binaries");
    // The stubs' functions keep their symbols (`_ZN16pbrlab_exercises7reflect…`).
    for binary in [built.worker, built.student] {
        let bytes = std::fs::read(&binary).expect("a worker binary");
        assert!(
            contains(&bytes, b"16pbrlab_exercises"),
            "{} does not link the student's crate",
            binary.display()
        );
    }
    for (name, binary) in [("pbrlab", &front), ("pbrlab-commands", &grader)] {
        assert!(
            !contains(binary, b"16pbrlab_exercises"),
            "the {name} binary links student code: a compile error in an exercise file would \
             stop `cargo run` before pbrlab starts"
        );
    }
}

/// The start of the legacy-mangled symbol of every function of `task`'s reference
/// (`_ZN16pbrlab_solutions8smith_g1…`): the reference's functions are reached only through
/// task tables, so each keeps a symbol of its own.
fn reference_symbol(task: TaskId) -> Vec<u8> {
    let module = task.name();
    format!("16pbrlab_solutions{}{module}", module.len()).into_bytes()
}

#[test]
fn no_worker_holds_the_reference_of_the_task_it_grades() {
    use pbrlab::grade::worker::ImplSpec;
    let grader = std::fs::read(crate::support::commands()).expect("the grader's binary");
    let worker = std::fs::read(crate::support::worker()).expect("the worker's binary");
    assert!(
        !contains(&worker, b"16pbrlab_solutions"),
        "the worker's binary links the reference"
    );
    for task in TaskId::ALL {
        let symbol = reference_symbol(task);
        // The grader links the reference, so the search finds what it looks for ...
        assert!(
            contains(&grader, &symbol),
            "{task:?}'s reference is not in the grader's binary"
        );
        // ... and the libraries a worker that grades `task` loads hold every task it may
        // take from the reference, and not `task`.
        let spec = ImplSpec::Mixed {
            student: vec![task.name().to_string()],
        };
        let libraries = pbrlab::grade::references::for_spec(&spec).expect("reference libraries");
        let others: Vec<TaskId> = TaskId::ALL.into_iter().filter(|t| *t != task).collect();
        assert_eq!(
            libraries
                .keys()
                .cloned()
                .collect::<std::collections::BTreeSet<_>>(),
            others.iter().map(|t| t.name().to_string()).collect()
        );
        for other in others {
            let path = &libraries[other.name()];
            let bytes = std::fs::read(path).expect("a reference library");
            assert!(
                contains(&bytes, &reference_symbol(other)),
                "{} lacks the reference of {other:?}",
                path.display()
            );
            assert!(
                !contains(&bytes, &symbol),
                "{} holds the reference of {task:?}, which it grades",
                path.display()
            );
        }
    }
}
