//! The one kind of channel the search uses: records addressed to a worker, exchanged by
//! timely dataflow and collected in the addressee's inbox; a round ends when timely's progress
//! tracking says no record of that round is in flight anywhere (the probe's frontier passed
//! it), so every worker then holds everything sent to it in the round. Records are kept by
//! round: a faster worker may already send the next round's records while this one still
//! waits for the end of the current round, and those must not be taken with it.

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::rc::Rc;
use timely::container::CapacityContainerBuilder;
use timely::dataflow::channels::pact::Exchange;
use timely::dataflow::operators::generic::operator::Operator;
use timely::dataflow::operators::vec::input::Input;
use timely::dataflow::operators::Probe;
use timely::dataflow::{InputHandleVec, ProbeHandle};
use timely::worker::Worker;

/// A record: the addressee, words, and small numbers (what they mean is the sender's and
/// addressee's business).
pub(crate) type Msg = (u64, Vec<u64>, Vec<u32>);

/// Bytes a record puts on the wire, about: its payload and three length words.
pub(crate) fn msg_bytes(m: &Msg) -> u64 {
    24 + m.1.len() as u64 * 8 + m.2.len() as u64 * 4
}

/// A channel of one worker: records go in at the current round, and come out at the addressee
/// once [`Channel::finish_round`] returns.
pub(crate) struct Channel {
    input: InputHandleVec<u64, Msg>,
    probe: ProbeHandle<u64>,
    /// The records received, by the round they were sent in.
    inbox: Rc<RefCell<BTreeMap<u64, Vec<Msg>>>>,
    /// Bytes of the records in the inbox.
    held: Rc<std::cell::Cell<u64>>,
    round: u64,
}

impl Channel {
    /// A new channel (a dataflow of its own) on `worker`.
    pub fn new(worker: &mut Worker) -> Channel {
        let mut input = InputHandleVec::new();
        let probe = ProbeHandle::new();
        let inbox = Rc::new(RefCell::new(BTreeMap::new()));
        let sink = Rc::clone(&inbox);
        let held = Rc::new(std::cell::Cell::new(0u64));
        let count = Rc::clone(&held);
        let p = probe.clone();
        worker.dataflow::<u64, _, _>(|scope| {
            scope
                .input_from(&mut input)
                .unary::<CapacityContainerBuilder<Vec<()>>, _, _, _>(
                    Exchange::new(|m: &Msg| m.0),
                    "Inbox",
                    move |_, _| {
                        move |input, _output| {
                            input.for_each(|cap, data| {
                                let b: u64 = data.iter().map(msg_bytes).sum();
                                count.set(count.get() + b);
                                sink.borrow_mut()
                                    .entry(cap.least().copied().unwrap_or_default())
                                    .or_insert_with(Vec::new)
                                    .append(data);
                            });
                        }
                    },
                )
                // After the inbox: the probe passes a round once the inbox took all of it.
                .probe_with(&p);
        });
        Channel {
            input,
            probe,
            inbox,
            held,
            round: 0,
        }
    }

    /// Send `m` to worker `m.0` in this round.
    pub fn send(&mut self, m: Msg) {
        self.input.send(m);
    }

    /// End the round: step the worker until every record of the round, from every worker,
    /// has reached its addressee; returns this worker's records of the round (records of a
    /// later round, sent by a worker that is ahead, stay for their round).
    pub fn finish_round(&mut self, worker: &mut Worker) -> Vec<Msg> {
        self.round += 1;
        self.input.advance_to(self.round);
        while self.probe.less_than(self.input.time()) {
            worker.step();
        }
        let mut inbox = self.inbox.borrow_mut();
        let later = inbox.split_off(&self.round);
        let done: Vec<Msg> = std::mem::replace(&mut *inbox, later)
            .into_values()
            .flatten()
            .collect();
        let taken: u64 = done.iter().map(msg_bytes).sum();
        self.held.set(self.held.get().saturating_sub(taken));
        done
    }

    /// Bytes of the records received so far in this round.
    pub fn inbox_bytes(&self) -> u64 {
        self.held.get()
    }

    /// Let records already sent move on (bounds what waits in buffers), without ending the
    /// round.
    pub fn flush(&mut self, worker: &mut Worker) {
        self.input.flush();
        worker.step();
    }
}
