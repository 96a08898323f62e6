//! The fan-out of frames from the loop to WatchFrames subscribers.
//!
//! The loop publishes into a bounded broadcast ring and never waits: a subscriber that falls more
//! than the ring behind loses the oldest frames, and its next frame says how many it lost
//! (`dropped_before`, computed from frame indices so that frames skipped on purpose by `every_k`
//! are not counted). Poses are only built while someone wants them, and are shared, not copied,
//! until the last step where each subscriber's message is encoded.

use std::sync::Arc;
use std::sync::atomic::{AtomicU32, Ordering};

use foveal_proto::pb;
use tokio::sync::{broadcast, mpsc};
use tokio_stream::wrappers::ReceiverStream;

use crate::shutdown::Shutdown;

/// One published frame.
#[derive(Debug)]
pub struct FrameMsg {
    /// The frame, without poses and with `dropped_before` 0.
    pub frame: pb::Frame,
    /// The frame's poses, present while at least one subscriber wants poses.
    pub poses: Option<Arc<pb::Poses>>,
    /// The frame's quantised poses, present while at least one subscriber wants them.
    pub quantised_poses: Option<Arc<pb::QuantisedPoses>>,
    /// The frame's collision list, present while at least one subscriber wants it.
    pub collisions: Option<Arc<pb::Collisions>>,
    /// The side by side's second collision list, present while the scene compares and at least
    /// one subscriber wants collisions.
    pub comparison_collisions: Option<Arc<pb::Collisions>>,
    /// Simulated by a Step: sent to every subscriber whatever its `every_k` (a frame someone
    /// asked to see one at a time).
    pub stepped: bool,
}

/// What a subscriber wants besides the frame's metrics.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Wants {
    /// f32 poses (`Frame.poses`).
    pub poses: bool,
    /// Quantised poses (`Frame.quantised_poses`).
    pub quantised_poses: bool,
    /// The collision list (`Frame.collisions`).
    pub collisions: bool,
}

impl Wants {
    /// From a WatchFrames request: quantised poses replace f32 poses when both are asked for.
    pub fn of(req: &pb::WatchFramesRequest) -> Self {
        Self {
            poses: req.include_poses && !req.quantised_poses,
            quantised_poses: req.include_poses && req.quantised_poses,
            collisions: req.include_collisions,
        }
    }
}

/// Broadcast ring plus subscriber counts.
#[derive(Debug)]
pub struct Fanout {
    tx: broadcast::Sender<Arc<FrameMsg>>,
    subscribers: AtomicU32,
    pose_subscribers: AtomicU32,
    quantised_subscribers: AtomicU32,
    collision_subscribers: AtomicU32,
}

impl Fanout {
    /// A fan-out keeping the last `capacity` frames for slow subscribers.
    pub fn new(capacity: usize) -> Self {
        let (tx, _) = broadcast::channel(capacity.max(1));
        Self {
            tx,
            subscribers: AtomicU32::new(0),
            pose_subscribers: AtomicU32::new(0),
            quantised_subscribers: AtomicU32::new(0),
            collision_subscribers: AtomicU32::new(0),
        }
    }

    /// Hand a frame to every subscriber; never blocks.
    pub fn publish(&self, msg: FrameMsg) {
        // Err only means nobody is subscribed right now.
        let _ = self.tx.send(Arc::new(msg));
    }

    /// Current subscribers.
    pub fn subscribers(&self) -> u32 {
        self.subscribers.load(Ordering::Relaxed)
    }

    /// Whether any subscriber wants poses (the loop builds them only then).
    pub fn wants_poses(&self) -> bool {
        self.pose_subscribers.load(Ordering::Relaxed) > 0
    }

    /// Whether any subscriber wants quantised poses.
    pub fn wants_quantised_poses(&self) -> bool {
        self.quantised_subscribers.load(Ordering::Relaxed) > 0
    }

    /// Whether any subscriber wants the collision list.
    pub fn wants_collisions(&self) -> bool {
        self.collision_subscribers.load(Ordering::Relaxed) > 0
    }

    #[cfg(test)]
    /// A new subscription receiving frames published from now on.
    pub fn subscribe(self: &Arc<Self>, every_k: u32, include_poses: bool) -> Subscription {
        self.subscribe_to(
            every_k,
            Wants {
                poses: include_poses,
                ..Wants::default()
            },
        )
    }

    /// A new subscription receiving frames published from now on, with what `wants` asks for.
    pub fn subscribe_to(self: &Arc<Self>, every_k: u32, wants: Wants) -> Subscription {
        self.subscribers.fetch_add(1, Ordering::Relaxed);
        for (wanted, count) in self.counters(wants) {
            if wanted {
                count.fetch_add(1, Ordering::Relaxed);
            }
        }
        Subscription {
            rx: self.tx.subscribe(),
            every_k: u64::from(every_k.max(1)),
            wants,
            last_sent: None,
            fanout: Arc::clone(self),
        }
    }

    fn counters(&self, wants: Wants) -> [(bool, &AtomicU32); 3] {
        [
            (wants.poses, &self.pose_subscribers),
            (wants.quantised_poses, &self.quantised_subscribers),
            (wants.collisions, &self.collision_subscribers),
        ]
    }
}

/// One subscriber's view of the fan-out; unsubscribes on drop.
#[derive(Debug)]
pub struct Subscription {
    rx: broadcast::Receiver<Arc<FrameMsg>>,
    every_k: u64,
    wants: Wants,
    last_sent: Option<u64>,
    fanout: Arc<Fanout>,
}

impl Drop for Subscription {
    fn drop(&mut self) {
        self.fanout.subscribers.fetch_sub(1, Ordering::Relaxed);
        for (wanted, count) in self.fanout.counters(self.wants) {
            if wanted {
                count.fetch_sub(1, Ordering::Relaxed);
            }
        }
    }
}

impl Subscription {
    /// The next frame for this subscriber (every k-th, with poses if asked, `dropped_before` set),
    /// or `None` once the fan-out is gone.
    pub async fn next(&mut self) -> Option<pb::Frame> {
        loop {
            let msg = match self.rx.recv().await {
                Ok(msg) => msg,
                // The count is recovered from indices below, which also excludes every_k skips.
                Err(broadcast::error::RecvError::Lagged(_)) => continue,
                Err(broadcast::error::RecvError::Closed) => return None,
            };
            let index = msg.frame.index;
            if index % self.every_k != 0 && !msg.stepped {
                continue;
            }
            // Only the first frame or so after subscribing can lack poses or collisions (published before the
            // loop saw this subscriber); it is skipped rather than sent incomplete.
            let w = self.wants;
            if (w.poses && msg.poses.is_none())
                || (w.quantised_poses && msg.quantised_poses.is_none())
                || (w.collisions && msg.collisions.is_none())
            {
                continue;
            }
            let mut frame = msg.frame.clone();
            frame.dropped_before = self.last_sent.map_or(0, |last| {
                (index / self.every_k).saturating_sub(last / self.every_k + 1)
            });
            if w.poses {
                frame.poses = msg.poses.as_deref().cloned();
            }
            if w.quantised_poses {
                frame.quantised_poses = msg.quantised_poses.as_deref().cloned();
            }
            if w.collisions {
                frame.collisions = msg.collisions.as_deref().cloned();
                if let Some(c) = frame.comparison.as_mut() {
                    c.collisions = msg.comparison_collisions.as_deref().cloned();
                }
            }
            self.last_sent = Some(index);
            return Some(frame);
        }
    }
}

/// Frames queued per subscriber between the fan-out and the connection: small, so that a slow
/// connection shows up as lag in the broadcast ring (and in `dropped_before`) instead of as
/// latency hidden in a deep queue.
const STREAM_QUEUE: usize = 2;

/// Serve a subscription as a WatchFrames response stream. The forwarding task ends when the client
/// goes away, the fan-out closes, or shutdown is triggered, which ends the stream cleanly.
pub fn into_stream(
    mut sub: Subscription,
    mut shutdown: Shutdown,
) -> ReceiverStream<Result<pb::Frame, tonic::Status>> {
    let (tx, rx) = mpsc::channel(STREAM_QUEUE);
    tokio::spawn(async move {
        loop {
            let frame = tokio::select! {
                _ = shutdown.wait() => break,
                _ = tx.closed() => break,
                frame = sub.next() => frame,
            };
            let Some(frame) = frame else { break };
            tokio::select! {
                _ = shutdown.wait() => break,
                sent = tx.send(Ok(frame)) => if sent.is_err() { break },
            }
        }
        tracing::debug!("WatchFrames subscriber finished");
    });
    ReceiverStream::new(rx)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn msg(index: u64, poses: bool) -> FrameMsg {
        FrameMsg {
            frame: pb::Frame {
                index,
                ..Default::default()
            },
            poses: poses.then(|| Arc::new(pb::Poses::default())),
            quantised_poses: None,
            collisions: None,
            comparison_collisions: None,
            stepped: false,
        }
    }

    #[tokio::test]
    async fn every_k_and_lag_give_exact_dropped_counts() {
        let fanout = Arc::new(Fanout::new(4));
        let mut sub = fanout.subscribe(2, false);
        assert_eq!(fanout.subscribers(), 1);
        assert!(!fanout.wants_poses());
        fanout.publish(msg(0, false));
        fanout.publish(msg(1, false));
        fanout.publish(msg(2, false));
        let f = sub.next().await.expect("frame");
        assert_eq!((f.index, f.dropped_before), (0, 0));
        let f = sub.next().await.expect("frame");
        assert_eq!((f.index, f.dropped_before), (2, 0));
        // Fall behind: 3..=12 published into a ring of 4; 10 and 12 survive, 4, 6, 8 are lost.
        for i in 3..=12 {
            fanout.publish(msg(i, false));
        }
        let f = sub.next().await.expect("frame");
        assert_eq!((f.index, f.dropped_before), (10, 3));
        drop(sub);
        assert_eq!(fanout.subscribers(), 0);
    }

    #[tokio::test]
    async fn pose_subscribers_skip_frames_without_poses() {
        let fanout = Arc::new(Fanout::new(8));
        let mut sub = fanout.subscribe(1, true);
        assert!(fanout.wants_poses());
        fanout.publish(msg(0, false));
        fanout.publish(msg(1, true));
        let f = sub.next().await.expect("frame");
        assert_eq!(f.index, 1);
        assert!(f.poses.is_some());
        drop(sub);
        assert!(!fanout.wants_poses());
    }
}
