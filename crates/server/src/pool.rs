//! The worker pool: solves run on blocking threads, at most `workers` at a time, with at most
//! `queue` more waiting; beyond that a request is refused at once (503). Each request has a
//! wall-clock deadline covering its wait and its solve (504 beyond). A panic inside a solve is
//! caught and answered as a 500 for that request alone.
//!
//! A solve that passes its deadline is answered at once; its thread runs on to the end and keeps
//! its worker until then, so the concurrency limit stays true. (Cancelling the running graph
//! needs the runtime's cancellation, which this pool will pass on when it exists.)

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Arc;
use std::time::Duration;

use axum::http::StatusCode;
use tokio::sync::Semaphore;
use tokio::time::Instant;

use crate::error::ApiError;

/// A bounded pool of solve workers.
#[derive(Debug)]
pub struct Pool {
    workers: Arc<Semaphore>,
    admitted: Arc<Semaphore>,
    worker_count: usize,
    queue: usize,
}

impl Pool {
    /// A pool of `workers` concurrent solves and `queue` waiting ones.
    pub fn new(workers: usize, queue: usize) -> Self {
        let workers = workers.max(1);
        Self {
            workers: Arc::new(Semaphore::new(workers)),
            admitted: Arc::new(Semaphore::new(workers + queue)),
            worker_count: workers,
            queue,
        }
    }

    /// The number of solves that may run at once.
    pub fn workers(&self) -> usize {
        self.worker_count
    }

    /// Runs `job` on a worker before `deadline` (measured from `start`).
    ///
    /// # Errors
    /// 503 when the queue is full, 504 when the deadline passes, 500 when the job panics, and
    /// whatever the job returns.
    pub async fn run<T, F>(&self, start: Instant, deadline: Duration, job: F) -> Result<T, ApiError>
    where
        T: Send + 'static,
        F: FnOnce() -> Result<T, ApiError> + Send + 'static,
    {
        let Ok(admission) = self.admitted.clone().try_acquire_owned() else {
            return Err(ApiError::new(
                StatusCode::SERVICE_UNAVAILABLE,
                "busy",
                format!(
                    "the server is busy: {} solves running and {} waiting; try again",
                    self.worker_count, self.queue
                ),
            ));
        };
        let end = start + deadline;
        let permit = match tokio::time::timeout_at(end, self.workers.clone().acquire_owned()).await
        {
            Ok(Ok(p)) => p,
            Ok(Err(_)) => return Err(ApiError::internal("the worker pool is closed")),
            Err(_) => return Err(deadline_error(deadline, "waiting for a worker")),
        };
        let task = tokio::task::spawn_blocking(move || {
            let _held = (permit, admission);
            catch_unwind(AssertUnwindSafe(job))
        });
        match tokio::time::timeout_at(end, task).await {
            Ok(Ok(Ok(result))) => result,
            Ok(Ok(Err(panic))) => Err(ApiError::internal(format!(
                "internal error while solving: {}; the server goes on",
                panic_text(&*panic)
            ))),
            Ok(Err(join)) => Err(ApiError::internal(format!("the solve failed: {join}"))),
            Err(_) => Err(deadline_error(deadline, "solving")),
        }
    }
}

fn deadline_error(deadline: Duration, during: &str) -> ApiError {
    ApiError::new(
        StatusCode::GATEWAY_TIMEOUT,
        "deadline",
        format!(
            "the request's deadline of {} ms passed while {during}",
            deadline.as_millis()
        ),
    )
}

fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic".to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn a_panicking_job_is_a_500_and_the_pool_goes_on() {
        let pool = Pool::new(1, 0);
        let start = Instant::now();
        let long = Duration::from_secs(10);
        let e = pool
            .run(start, long, || -> Result<(), ApiError> { panic!("boom") })
            .await
            .unwrap_err();
        assert_eq!(e.status, StatusCode::INTERNAL_SERVER_ERROR);
        assert!(e.message.contains("boom"), "{}", e.message);
        assert_eq!(pool.run(Instant::now(), long, || Ok(7)).await, Ok(7));
    }

    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn deadlines_and_a_full_queue_are_refused() {
        let pool = std::sync::Arc::new(Pool::new(1, 0));
        let e = pool
            .run(Instant::now(), Duration::from_millis(20), || {
                std::thread::sleep(Duration::from_millis(300));
                Ok(())
            })
            .await
            .unwrap_err();
        assert_eq!(e.status, StatusCode::GATEWAY_TIMEOUT);
        // The late solve still holds the only worker: a second request finds the queue full.
        let e = pool
            .run(Instant::now(), Duration::from_secs(5), || Ok(()))
            .await
            .unwrap_err();
        assert_eq!(e.status, StatusCode::SERVICE_UNAVAILABLE);
        tokio::time::sleep(Duration::from_millis(400)).await;
        assert_eq!(
            pool.run(Instant::now(), Duration::from_secs(5), || Ok(1))
                .await,
            Ok(1)
        );
    }
}
