//! The progress shown on standard error by the long commands (`render`, `demo`, `unwrap`).

/// A spinner on standard error naming the stage at work, a bar over the passes of a multi-pass
/// render; indicatif hides both when standard error is not a terminal (logs, pipes, tests).
pub(crate) struct Progress(indicatif::ProgressBar);

impl Progress {
    /// A spinner with no stage yet.
    pub(crate) fn start() -> Self {
        let bar = indicatif::ProgressBar::new_spinner();
        if let Ok(style) = indicatif::ProgressStyle::with_template("{spinner} {msg} {elapsed}") {
            bar.set_style(style);
        }
        bar.enable_steady_tick(std::time::Duration::from_millis(100));
        Self(bar)
    }

    /// Runs `f` with the spinner hidden (for a line on standard output).
    pub(crate) fn suspend<R>(&self, f: impl FnOnce() -> R) -> R {
        self.0.suspend(f)
    }

    /// Names the stage at work.
    pub(crate) fn stage(&self, what: impl Into<std::borrow::Cow<'static, str>>) {
        self.0.set_message(what);
    }

    /// After pass `done` of `planned`: a bar once there is more than one pass.
    pub(crate) fn passes(&self, done: u32, planned: u32) {
        if planned <= 1 {
            return;
        }
        if self.0.length() != Some(u64::from(planned)) {
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{msg} [{bar:32}] pass {pos}/{len} {elapsed} (eta {eta})",
            ) {
                self.0.set_style(style.progress_chars("=> "));
            }
            self.0.set_length(u64::from(planned));
        }
        self.0.set_position(u64::from(done));
    }

    /// Clears the spinner or bar.
    pub(crate) fn finish(&self) {
        self.0.finish_and_clear();
    }
}

impl Drop for Progress {
    /// Clears the spinner on the error paths too.
    fn drop(&mut self) {
        self.0.finish_and_clear();
    }
}
