//! Lowering a checked system to the IR. **This module is the step semantics**: every rule of
//! `docs/semantics.md` is decided here, once, and every consumer runs the result.
//!
//! The rules, in the order a tick applies them (see docs/semantics.md for worked examples):
//! - R1 Tick 0 only initialises: every instance, in execution order, performs its default
//!   entry (entry actions outermost first, `initial` children, regions in order).
//! - R2 Later ticks run every instance's step in execution order; observers run last. In an
//!   interleaved system only the instances of the unit named by the input `sched.unit` step.
//! - R3 At the start of an instance's step, its output events are cleared, and local events
//!   raised in the previous tick become present (those raised now are present next tick).
//! - R4 The step walks the active configuration top-down. For an active state: its timer
//!   advances; its transitions are tried in priority order; the first enabled one fires and
//!   ends the walk below that state for this tick. If none fires: `during`, then the active
//!   child (OR) or every region in order (AND).
//! - R5 Firing: exit the source's branch below the transition's scope (innermost first,
//!   regions in reverse order), run the transition action, the taken choice branches'
//!   actions, then enter from the scope down to the target (outermost first), then the
//!   target's default entry. The scope is the innermost exclusive node that strictly contains
//!   both source and target (so self-transitions and transitions to a descendant exit and
//!   re-enter the source).
//! - R6 A transition that leaves a parallel state stops the walk of its later regions.
//! - R7 A choice fires only if some branch path ends in a state; branch guards see the values
//!   before the transition's actions.
//! - R8 Default entry of an OR state with history re-enters the remembered child (shallow:
//!   that child's default entry; deep: the remembered configuration all the way down).
//! - R9 Assigning a value out of the variable's range, dividing by zero or shifting by a bad
//!   amount is a run-time error: the tick stops there.

use crate::layout::{layout, Layout};

use crate::program::*;
use statecheck_base::{Diagnostic, Span};
use statecheck_model::{Chart, Model, NodeKind, StateId, System};
use statecheck_syntax::ast::{BinOp, VarKind};
use std::collections::HashMap;

mod entry_exit;
mod fire;
mod monitor;
mod stmt;

/// Lower one system of a checked model. The model must have no errors; structural problems
/// only the lowering can see (e.g. a transition that would leave a chart-level parallel
/// state) are returned as diagnostics.
pub fn lower(model: &Model, sys: &System) -> Result<Program, Vec<Diagnostic>> {
    let lay = layout(model, sys);
    let mut lw = Lowerer {
        model,
        sys,
        nodes: Vec::new(),
        procs: Vec::new(),
        sites: Vec::new(),
        covers: Vec::new(),
        exit_procs: HashMap::new(),
        enter_procs: HashMap::new(),
        state_covers: HashMap::new(),
        locals: HashMap::new(),
        diags: Vec::new(),
        lay,
    };
    let program = lw.run();
    if lw.diags.is_empty() {
        Ok(program)
    } else {
        Err(lw.diags)
    }
}

struct Lowerer<'m> {
    model: &'m Model,
    sys: &'m System,
    lay: Layout,
    nodes: Vec<Node>,
    procs: Vec<Proc>,
    sites: Vec<Site>,
    covers: Vec<Cover>,
    exit_procs: HashMap<(u32, StateId), ProcId>,
    enter_procs: HashMap<(u32, StateId, bool), ProcId>,
    state_covers: HashMap<(u32, StateId), CoverId>,
    /// Model `Let` ids to expression locals.
    locals: HashMap<u32, u32>,
    diags: Vec<Diagnostic>,
}

/// The instance being lowered and the state whose code is being generated (for sites).
#[derive(Clone, Copy)]
struct Ctx {
    inst: u32,
    state: StateId,
}

impl<'m> Lowerer<'m> {
    fn chart(&self, inst: u32) -> &'m Chart {
        &self.model.charts[self.sys.instances[inst as usize].chart as usize]
    }

    fn node(&mut self, n: Node) -> ExprId {
        self.nodes.push(n);
        self.nodes.len() as ExprId - 1
    }

    fn konst(&mut self, v: i64) -> ExprId {
        self.node(Node::Const(v))
    }

    fn slot(&mut self, s: SlotId) -> ExprId {
        self.node(Node::Slot(s))
    }

    fn bin(&mut self, op: BinOp, a: ExprId, b: ExprId) -> ExprId {
        self.node(Node::Binary(op, a, b, u32::MAX))
    }

    fn site(&mut self, ctx: Option<Ctx>, span: Span, what: String) -> SiteId {
        let (instance, state) = match ctx {
            Some(c) => (
                Some(c.inst),
                self.chart(c.inst).states[c.state as usize].path.clone(),
            ),
            None => (None, String::new()),
        };
        self.sites.push(Site {
            span,
            instance,
            state,
            what,
        });
        self.sites.len() as SiteId - 1
    }

    fn new_proc(&mut self, name: String) -> ProcId {
        self.procs.push(Proc {
            name,
            body: Vec::new(),
        });
        self.procs.len() as ProcId - 1
    }

    fn run(&mut self) -> Program {
        // `in(state)` of every state of every instance.
        for i in 0..self.sys.instances.len() as u32 {
            let chart = self.chart(i);
            let mut active = Vec::with_capacity(chart.states.len());
            for s in 0..chart.states.len() as StateId {
                let mut conj: Option<ExprId> = None;
                for n in chart.ancestry(s) {
                    let Some(p) = chart.states[n as usize].parent else {
                        continue;
                    };
                    if let NodeKind::Or { children, .. } = &chart.states[p as usize].kind {
                        let idx = children.iter().position(|c| *c == n).unwrap_or(0) as i64;
                        let slot =
                            self.lay.instances[i as usize].region_slots[p as usize].unwrap_or(0);
                        let sv = self.slot(slot);
                        let kv = self.konst(idx);
                        let eq = self.bin(BinOp::Eq, sv, kv);
                        conj = Some(match conj {
                            Some(c) => self.bin(BinOp::And, c, eq),
                            None => eq,
                        });
                    }
                }
                let e = match conj {
                    Some(e) => e,
                    None => self.konst(1),
                };
                active.push(e);
            }
            self.lay.instances[i as usize].active = active;
        }
        // State coverage items, in instance and state order.
        for i in 0..self.sys.instances.len() as u32 {
            let chart = self.chart(i);
            for (s, node) in chart.states.iter().enumerate() {
                if s == 0 || node.is_region {
                    continue;
                }
                self.covers.push(Cover {
                    instance: i,
                    kind: CoverKind::State(s as StateId),
                    label: node.path.clone(),
                    span: node.span,
                    expected_unreached: chart.is_observer_error(s as StateId),
                });
                self.state_covers
                    .insert((i, s as StateId), self.covers.len() as CoverId - 1);
            }
        }
        let mut init_calls = Vec::new();
        let mut step_calls = Vec::new();
        // Interleaved (`system S interleaved`): a unit's instances step only in a tick whose
        // scheduler input names the unit; the others keep their whole state (timers, events
        // raised in their last step) until their next step. Tick 0 initialises every unit.
        let sched = self.sys.interleaved.as_ref().map(|il| {
            let slot = self.lay.instances[il.scheduler as usize]
                .var_slots
                .first()
                .copied()
                .unwrap_or(0);
            (slot, il.unit.clone())
        });
        for &i in &self.sys.order {
            let (init, step) = self.instance(i);
            init_calls.push(Stmt::Call(init));
            match sched
                .as_ref()
                .and_then(|(s, u)| Some((*s, (*u.get(i as usize)?)?)))
            {
                Some((slot, unit)) => {
                    let sv = self.slot(slot);
                    let uv = self.konst(unit as i64);
                    let cond = self.bin(BinOp::Eq, sv, uv);
                    step_calls.push(Stmt::If {
                        cond,
                        then: vec![Stmt::Call(step)],
                        otherwise: Vec::new(),
                    });
                }
                None => step_calls.push(Stmt::Call(step)),
            }
        }
        let started = self.lay.started;
        let started_e = self.slot(started);
        let one = self.konst(1);
        let mut init_block = vec![Stmt::Assign {
            slot: started,
            expr: one,
            site: None,
        }];
        init_block.extend(init_calls);
        let mut step = vec![Stmt::If {
            cond: started_e,
            then: step_calls,
            otherwise: init_block,
        }];
        step.extend(self.monitors());
        let assumes = self
            .sys
            .assumes
            .iter()
            .map(|a| self.expr(a, None))
            .collect();
        let properties = self.properties();
        let (temporal, fairness) = {
            let props = &self.sys.properties;
            crate::temporal::lower(props, &mut |e| self.expr(e, None))
        };
        Program {
            name: self.sys.name.clone(),
            slots: std::mem::take(&mut self.lay.slots),
            n_state: self.lay.n_state,
            inputs: std::mem::take(&mut self.lay.inputs),
            nodes: std::mem::take(&mut self.nodes),
            procs: std::mem::take(&mut self.procs),
            step,
            sites: std::mem::take(&mut self.sites),
            covers: std::mem::take(&mut self.covers),
            instances: std::mem::take(&mut self.lay.instances),
            order: self.sys.order.clone(),
            assumes,
            properties,
            temporal,
            fairness,
            started,
            n_locals: self.locals.len(),
            tick_ms: self.model.tick_ms,
            run_cache: Default::default(),
        }
    }

    /// The init and step procedures of one instance.
    fn instance(&mut self, i: u32) -> (ProcId, ProcId) {
        let chart = self.chart(i);
        let name = sanitize(&self.sys.instances[i as usize].name);
        let init = self.new_proc(format!("init_{name}"));
        let step = self.new_proc(format!("step_{name}"));
        // R3: clear output events; local events raised last tick become present.
        let mut prologue = Vec::new();
        for (v, var) in chart.vars.iter().enumerate() {
            if !var.is_event {
                continue;
            }
            let slot = self.lay.instances[i as usize].var_slots[v];
            match var.kind {
                VarKind::Output => {
                    let z = self.konst(0);
                    prologue.push(Stmt::Assign {
                        slot,
                        expr: z,
                        site: None,
                    });
                }
                VarKind::Local => {
                    if let Some(p) = self.lay.pending[i as usize][v] {
                        let pe = self.slot(p);
                        prologue.push(Stmt::Assign {
                            slot,
                            expr: pe,
                            site: None,
                        });
                        let z = self.konst(0);
                        prologue.push(Stmt::Assign {
                            slot: p,
                            expr: z,
                            site: None,
                        });
                    }
                }
                VarKind::Input => {}
            }
        }
        for a in self.lay.aborts[i as usize].clone().into_iter().flatten() {
            let z = self.konst(0);
            prologue.push(Stmt::Assign {
                slot: a,
                expr: z,
                site: None,
            });
        }
        // R1: tick 0 is the default entry of the root.
        let mut init_body = prologue.clone();
        let root_entry = self.enter_default(i, 0, false);
        init_body.push(Stmt::Call(root_entry));
        self.procs[init as usize].body = init_body;
        // R2/R4: later ticks walk the configuration.
        let mut step_body = prologue;
        step_body.extend(self.visit(i, 0));
        self.procs[step as usize].body = step_body;
        (init, step)
    }
}

/// A name usable as an identifier in generated code.
pub fn sanitize(s: &str) -> String {
    let out: String = s
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if out.is_empty() {
        "root".into()
    } else {
        out
    }
}
