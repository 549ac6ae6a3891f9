//! Single key presses for `pbrlab watch` (h, r, q as rustlings has them): standard input
//! read byte by byte on a thread of its own. On a terminal, line editing, echo and the
//! interrupt signal are turned off while watching (output processing stays on, so the
//! tables printed meanwhile keep their layout), so Ctrl-C arrives as a key that ends the
//! watch the same way q does, and the terminal is put back as it was.

use std::io::Read;
use std::sync::mpsc::{Receiver, RecvTimeoutError, channel};
use std::time::Duration;

/// What Ctrl-C and Ctrl-D send on a terminal without signals and line editing.
const CTRL_C: u8 = 3;
const CTRL_D: u8 = 4;

/// Key presses as they come; dropping it puts the terminal back as it was.
pub struct Keys {
    presses: Receiver<u8>,
    #[cfg(unix)]
    restore: Option<rustix::termios::Termios>,
}

impl Keys {
    /// Starts reading standard input. A terminal is switched to one key at a time without
    /// echo; a pipe or a file is read as it is (its end means no more keys).
    pub fn start() -> Keys {
        #[cfg(unix)]
        let restore = one_key_at_a_time();
        let (send, presses) = channel();
        std::thread::spawn(move || {
            let mut stdin = std::io::stdin().lock();
            let mut byte = [0u8];
            while let Ok(1) = stdin.read(&mut byte) {
                if send.send(byte[0]).is_err() {
                    break;
                }
            }
        });
        Keys {
            presses,
            #[cfg(unix)]
            restore,
        }
    }

    /// The next key pressed within `wait`, if any, in lower case; Ctrl-C and Ctrl-D read
    /// as `q`.
    pub fn next(&self, wait: Duration) -> Option<char> {
        match self.presses.recv_timeout(wait) {
            Ok(CTRL_C | CTRL_D) => Some('q'),
            Ok(byte) => Some(char::from(byte).to_ascii_lowercase()),
            Err(RecvTimeoutError::Timeout) => None,
            Err(RecvTimeoutError::Disconnected) => {
                // Standard input ended: nothing more will come, so just wait out the time.
                std::thread::sleep(wait);
                None
            }
        }
    }
}

/// Turns off line editing, echo and signals on a terminal standard input; the settings to
/// put back.
#[cfg(unix)]
fn one_key_at_a_time() -> Option<rustix::termios::Termios> {
    use rustix::termios::{LocalModes, OptionalActions, SpecialCodeIndex, tcgetattr, tcsetattr};
    let stdin = std::io::stdin();
    let before = tcgetattr(&stdin).ok()?;
    let mut keys = before.clone();
    keys.local_modes
        .remove(LocalModes::ICANON | LocalModes::ECHO | LocalModes::ISIG);
    keys.special_codes[SpecialCodeIndex::VMIN] = 1;
    keys.special_codes[SpecialCodeIndex::VTIME] = 0;
    tcsetattr(&stdin, OptionalActions::Now, &keys).ok()?;
    Some(before)
}

#[cfg(unix)]
impl Drop for Keys {
    fn drop(&mut self) {
        if let Some(before) = &self.restore {
            let _ = rustix::termios::tcsetattr(
                std::io::stdin(),
                rustix::termios::OptionalActions::Now,
                before,
            );
        }
    }
}
