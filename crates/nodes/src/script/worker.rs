//! Script worker processes: starting them, holding each call to its time limit, and keeping
//! idle ones for the next evaluation.
//!
//! A worker is `PYTHON` running `locus._script_worker`, a child process that speaks
//! [`protocol`](super::protocol) on its standard input and output. Nothing a script does can
//! reach the engine's process: a script that never returns is stopped (the process is killed
//! when an iteration passes its time limit plus [`HARD_LIMIT_GRACE`]), and a script that ends
//! its process (`os._exit`, a crash in a C extension, running out of memory) is reported as an
//! error on the iteration it was running. A worker that was killed or died is not reused; the
//! next evaluation starts a new one.
//!
//! A [`WorkerPool`] belongs to one registration of the node type (one registry). A node's
//! evaluation takes an idle worker or starts one, and gives it back afterwards, so that a
//! graph's script nodes running in parallel each have their own process, and a host's many
//! evaluators share the started ones. Replies are read by a thread per worker, so that waiting
//! for one has a timeout on every platform.

use std::collections::VecDeque;
use std::ffi::OsString;
use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError, channel};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};

use super::protocol::{Outcome, PROTOCOL_VERSION, Reply, read_frame, write_frame};

/// How long a new worker may take to start Python and import the `locus` package (slow on a
/// loaded machine: numpy is imported too).
pub const STARTUP_TIMEOUT: Duration = Duration::from_secs(60);

/// How much longer than its time limit the engine waits for an iteration before it stops the
/// worker. The worker stops a Python script itself at the time limit (an exception in the
/// script); this margin is for code that does not return to Python (a long call into C).
pub const HARD_LIMIT_GRACE: Duration = Duration::from_secs(2);

/// After Python was found not to be available, how long the pool answers so without trying
/// to start it again (so that a graph of many script nodes does not start a failing
/// interpreter for each).
pub const UNAVAILABLE_RETRY: Duration = Duration::from_secs(5);

/// How many bytes of a worker's standard error are kept to explain why it ended.
const STDERR_TAIL_BYTES: usize = 4096;

/// What a worker process runs: `locus._script_worker`, imported with the working folder left
/// off the module path, so that a `locus` folder there (the package's sources in a checkout)
/// cannot stand in for the installed package. The worker puts the folder back, last, for
/// scripts.
const WORKER_MAIN: &str = concat!(
    "import sys; sys.path[:] = [p for p in sys.path if p not in ('', '.')]; ",
    "from locus._script_worker import main; sys.exit(main())",
);

/// The environment variable that names the Python interpreter to run scripts with.
pub const PYTHON_ENV: &str = "LOCUS_PYTHON";

/// Which Python runs scripts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PythonConfig {
    /// The interpreter named by `$LOCUS_PYTHON` when it is set, else `python3` (`python` on
    /// Windows), found on the `PATH` when the first script runs.
    FromEnvironment,
    /// This interpreter (the `locus` Python package passes its own, `sys.executable`).
    Interpreter(OsString),
    /// Scripts do not run; the text says why (for the node's error).
    Disabled(String),
}

impl PythonConfig {
    /// The interpreter to start, or why scripts do not run.
    fn interpreter(&self) -> Result<OsString, String> {
        match self {
            PythonConfig::FromEnvironment => Ok(std::env::var_os(PYTHON_ENV)
                .filter(|p| !p.is_empty())
                .unwrap_or_else(|| {
                    OsString::from(if cfg!(windows) { "python" } else { "python3" })
                })),
            PythonConfig::Interpreter(p) => Ok(p.clone()),
            PythonConfig::Disabled(why) => Err(why.clone()),
        }
    }
}

/// What the engine knows about a started worker's Python.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WorkerInfo {
    /// The interpreter it was started with.
    pub interpreter: String,
    /// The version of its `locus` package.
    pub package_version: String,
    /// Its Python version.
    pub python_version: String,
}

/// A started worker process.
struct Worker {
    child: Child,
    stdin: Option<ChildStdin>,
    replies: Receiver<Result<Vec<u8>, String>>,
    stderr: Arc<Mutex<VecDeque<u8>>>,
    info: WorkerInfo,
}

impl std::fmt::Debug for Worker {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Worker")
            .field("pid", &self.child.id())
            .field("info", &self.info)
            .finish_non_exhaustive()
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        // Closing its input ends an idle worker; a busy or stuck one is killed. Either way it
        // is waited for, so that no zombie is left.
        drop(self.stdin.take());
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The last line of what a worker wrote to its standard error, if any.
fn stderr_tail(stderr: &Mutex<VecDeque<u8>>) -> Option<String> {
    let bytes = stderr.lock().unwrap_or_else(PoisonError::into_inner);
    let (a, b) = bytes.as_slices();
    let text = String::from_utf8_lossy(&[a, b].concat()).into_owned();
    text.lines()
        .map(str::trim)
        .rfind(|l| !l.is_empty())
        .map(str::to_owned)
}

impl Worker {
    /// Starts a worker and waits for its hello.
    fn start(interpreter: &OsString) -> Result<Self, String> {
        let shown = interpreter.to_string_lossy().into_owned();
        let mut child = Command::new(interpreter)
            .args(["-u", "-c", WORKER_MAIN])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .env("PYTHONDONTWRITEBYTECODE", "1")
            .spawn()
            .map_err(|e| format!("cannot start {shown}: {e}"))?;
        let (Some(stdin), Some(stdout), Some(stderr_pipe)) =
            (child.stdin.take(), child.stdout.take(), child.stderr.take())
        else {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("cannot open the pipes of {shown}"));
        };
        let (send, replies) = channel();
        std::thread::Builder::new()
            .name("locus-script-reader".to_owned())
            .spawn(move || {
                let mut stdout = BufReader::new(stdout);
                loop {
                    let frame = match read_frame(&mut stdout) {
                        Ok(Some(bytes)) => Ok(bytes),
                        Ok(None) => break,
                        Err(e) => Err(e.to_string()),
                    };
                    let failed = frame.is_err();
                    if send.send(frame).is_err() || failed {
                        break;
                    }
                }
            })
            .map_err(|e| format!("cannot start a thread to read {shown}: {e}"))?;
        let stderr = Arc::new(Mutex::new(VecDeque::new()));
        let tail = stderr.clone();
        std::thread::Builder::new()
            .name("locus-script-stderr".to_owned())
            .spawn(move || {
                let mut lines = BufReader::new(stderr_pipe);
                let mut line = Vec::new();
                while matches!(lines.read_until(b'\n', &mut line), Ok(n) if n > 0) {
                    let mut kept = tail.lock().unwrap_or_else(PoisonError::into_inner);
                    kept.extend(line.drain(..));
                    while kept.len() > STDERR_TAIL_BYTES {
                        kept.pop_front();
                    }
                }
            })
            .map_err(|e| format!("cannot start a thread to read {shown}: {e}"))?;
        let mut worker = Self {
            child,
            stdin: Some(stdin),
            replies,
            stderr,
            info: WorkerInfo {
                interpreter: shown.clone(),
                package_version: String::new(),
                python_version: String::new(),
            },
        };
        match worker.receive(STARTUP_TIMEOUT) {
            Received::Reply(Reply::Hello {
                protocol,
                version,
                python,
            }) => {
                if protocol != PROTOCOL_VERSION {
                    return Err(format!(
                        "the locus package of {shown} (version {version}) speaks script protocol \
                         {protocol}, this engine speaks {PROTOCOL_VERSION}: install the package of \
                         the same release (pip install ./python)"
                    ));
                }
                worker.info.package_version = version;
                worker.info.python_version = python;
                Ok(worker)
            }
            Received::Reply(other) => Err(format!(
                "{shown} (locus._script_worker) answered {other:?} instead of its hello"
            )),
            Received::Timeout => Err(format!(
                "{shown} (locus._script_worker) did not start within {} s",
                STARTUP_TIMEOUT.as_secs()
            )),
            Received::Ended(why) => Err(format!("{shown} (locus._script_worker) {why}")),
        }
    }

    /// Waits up to `wait` for the next reply.
    fn receive(&mut self, wait: Duration) -> Received {
        match self.replies.recv_timeout(wait) {
            Ok(Ok(bytes)) => match Reply::decode(&bytes) {
                Ok(reply) => Received::Reply(reply),
                Err(e) => Received::Ended(format!("sent a message that does not read: {e}")),
            },
            Ok(Err(e)) => Received::Ended(format!("broke its output stream: {e}")),
            Err(RecvTimeoutError::Timeout) => Received::Timeout,
            Err(RecvTimeoutError::Disconnected) => Received::Ended(self.ended()),
        }
    }

    /// Why the process ended (it has closed its output): its exit status and the last line
    /// it wrote to its standard error.
    fn ended(&mut self) -> String {
        // The output closes an instant before the process is reaped.
        let deadline = Instant::now() + Duration::from_secs(2);
        let status = loop {
            match self.child.try_wait() {
                Ok(Some(status)) => break Some(status),
                Ok(None) if Instant::now() < deadline => {
                    std::thread::sleep(Duration::from_millis(5));
                }
                _ => break None,
            }
        };
        // Let the standard error reader take the last lines.
        std::thread::sleep(Duration::from_millis(20));
        let how = match status.and_then(|s| s.code()) {
            Some(code) => format!("ended with exit code {code}"),
            None => match status {
                Some(s) => format!("was ended ({s})"),
                None => "closed its output".to_owned(),
            },
        };
        match stderr_tail(&self.stderr) {
            Some(line) => format!("{how}: {line}"),
            None => how,
        }
    }

    /// Sends a request and collects one outcome per iteration. Returns whether the worker can
    /// be used again.
    fn run(
        &mut self,
        request: &[u8],
        iterations: usize,
        time_limit: Duration,
    ) -> (Vec<Result<Outcome, String>>, bool) {
        let mut outcomes = Vec::with_capacity(iterations);
        let sent = match self.stdin.as_mut() {
            Some(stdin) => write_frame(stdin, request).and_then(|()| stdin.flush()),
            None => Err(std::io::ErrorKind::BrokenPipe.into()),
        };
        if let Err(e) = sent {
            let why = match self.replies.recv_timeout(Duration::from_secs(2)) {
                Err(RecvTimeoutError::Disconnected) => self.ended(),
                _ => format!("could not be sent the script's data: {e}"),
            };
            fill(
                &mut outcomes,
                iterations,
                &format!("the Python process {why}"),
            );
            return (outcomes, false);
        }
        // Reading a large request takes the worker a while before the first iteration: allow
        // a tenth of a second per megabyte.
        let reading = Duration::from_millis((request.len() / 10_000) as u64);
        let mut wait = time_limit + HARD_LIMIT_GRACE + reading;
        while outcomes.len() < iterations {
            match self.receive(wait) {
                Received::Reply(Reply::Done(outcome)) => outcomes.push(Ok(outcome)),
                Received::Reply(Reply::Fatal(why)) => {
                    fill(
                        &mut outcomes,
                        iterations,
                        &format!("the script did not run: {why}"),
                    );
                    return (outcomes, true);
                }
                Received::Reply(Reply::Hello { .. }) => {
                    let why = "the Python process sent a second hello".to_owned();
                    fill(&mut outcomes, iterations, &why);
                    return (outcomes, false);
                }
                Received::Timeout => {
                    let _ = self.child.kill();
                    outcomes.push(Err(format!(
                        "the script did not finish within its time limit of {} s: its Python \
                         process was stopped",
                        super::format_seconds(time_limit)
                    )));
                    fill(
                        &mut outcomes,
                        iterations,
                        "not run: the Python process was stopped at an earlier item",
                    );
                    return (outcomes, false);
                }
                Received::Ended(why) => {
                    outcomes.push(Err(format!(
                        "the Python process {why} while the script ran"
                    )));
                    fill(
                        &mut outcomes,
                        iterations,
                        "not run: the Python process ended at an earlier item",
                    );
                    return (outcomes, false);
                }
            }
            wait = time_limit + HARD_LIMIT_GRACE;
        }
        (outcomes, true)
    }
}

/// Fills the outcomes up to `n` with the error `why`.
fn fill(outcomes: &mut Vec<Result<Outcome, String>>, n: usize, why: &str) {
    while outcomes.len() < n {
        outcomes.push(Err(why.to_owned()));
    }
}

enum Received {
    Reply(Reply),
    Timeout,
    Ended(String),
}

/// Started workers of one registration of the script node, and how to start more.
#[derive(Debug)]
pub struct WorkerPool {
    config: PythonConfig,
    max_idle: usize,
    idle: Mutex<Vec<Worker>>,
    /// When Python was last found not to be available, and why.
    unavailable: Mutex<Option<(Instant, String)>>,
}

impl WorkerPool {
    /// A pool that starts workers as `config` says and keeps up to one idle worker per core.
    pub fn new(config: PythonConfig) -> Self {
        let cores = std::thread::available_parallelism().map_or(1, usize::from);
        Self {
            config,
            max_idle: cores,
            idle: Mutex::new(Vec::new()),
            unavailable: Mutex::new(None),
        }
    }

    /// Runs a request (encoded, with `iterations` iterations) on an idle or new worker:
    /// one outcome, or the reason it has none, per iteration.
    ///
    /// # Errors
    /// "Python is not available" with the reason, when no worker can be started.
    pub fn run(
        &self,
        request: &[u8],
        iterations: usize,
        time_limit: Duration,
    ) -> Result<Vec<Result<Outcome, String>>, String> {
        let mut worker = self.take()?;
        let (outcomes, reusable) = worker.run(request, iterations, time_limit);
        if reusable {
            let mut idle = self.idle.lock().unwrap_or_else(PoisonError::into_inner);
            if idle.len() < self.max_idle {
                idle.push(worker);
            }
        }
        Ok(outcomes)
    }

    /// What the Python that runs scripts is, starting a worker if none is idle.
    ///
    /// # Errors
    /// As [`WorkerPool::run`].
    pub fn info(&self) -> Result<WorkerInfo, String> {
        let worker = self.take()?;
        let info = worker.info.clone();
        self.idle
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .push(worker);
        Ok(info)
    }

    fn take(&self) -> Result<Worker, String> {
        loop {
            let candidate = self
                .idle
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .pop();
            match candidate {
                Some(mut w) => {
                    if matches!(w.child.try_wait(), Ok(None)) {
                        return Ok(w);
                    }
                }
                None => break,
            }
        }
        {
            let unavailable = self
                .unavailable
                .lock()
                .unwrap_or_else(PoisonError::into_inner);
            if let Some((when, why)) = &*unavailable
                && when.elapsed() < UNAVAILABLE_RETRY
            {
                return Err(why.clone());
            }
        }
        let started = self
            .config
            .interpreter()
            .map_err(|why| format!("Python scripts are disabled: {why}"))
            .and_then(|interpreter| {
                Worker::start(&interpreter).map_err(|why| {
                    format!(
                        "Python is not available: {why} (set {PYTHON_ENV} to a Python with the \
                         locus package installed: pip install ./python)"
                    )
                })
            });
        match started {
            Ok(w) => Ok(w),
            Err(why) => {
                *self
                    .unavailable
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner) = Some((Instant::now(), why.clone()));
                Err(why)
            }
        }
    }
}
