//! The commands `pbrlab` hands over: `pbrlab-commands --help` lists them all, the three
//! the `pbrlab` binary runs itself among them (one command line, whichever binary runs it).

use std::process::Command;

#[test]
fn the_full_command_line_lists_the_commands_the_front_runs_itself() {
    let out = Command::new(env!("CARGO_BIN_EXE_pbrlab-commands"))
        .arg("--help")
        .output()
        .expect("pbrlab-commands runs");
    assert!(out.status.success(), "{out:?}");
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(
        help.contains("Usage: pbrlab "),
        "named pbrlab, not its file: {help}"
    );
    let listed: Vec<&str> = help
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    for command in pbrlab_course::cli::LightCommand::NAMES {
        assert!(
            listed.contains(&command),
            "{command} missing from {listed:?}"
        );
    }
    for command in ["grade", "watch", "render", "stability", "converge"] {
        assert!(
            listed.contains(&command),
            "{command} missing from {listed:?}"
        );
    }
}
