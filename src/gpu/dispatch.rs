//! Dispatch: a stage over a range of items, split into dispatches of at
//! most the device's workgroups per dimension, each with its own Params.

use wgpu::util::DeviceExt;

use super::layout::Params;
use super::pipelines::{Stage, WORKGROUP};
use super::GpuContext;

/// Items first..first + count of a table, `per_group` per workgroup, and
/// what the shader's Params carry besides the range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Span {
    pub first: u32,
    pub count: u32,
    /// Items per workgroup: [`WORKGROUP`] (one per invocation), or 1 (the
    /// workgroup kernel: one island per workgroup).
    pub per_group: u32,
    /// Params.budget: loop work per invocation and round (enumeration).
    pub budget: u32,
    /// Params.flags (the tree kernel: semidefinite).
    pub flags: u32,
}

impl Span {
    /// Items first..first + count, one per invocation, budget and flags 0.
    pub(crate) fn items(first: u32, count: u32) -> Self {
        Span {
            first,
            count,
            per_group: WORKGROUP,
            budget: 0,
            flags: 0,
        }
    }
}

/// `span` in dispatches of at most `max_groups` workgroups (the
/// per-dimension limit): each dispatch's Params pushed on `params`, and
/// (its index there, its workgroups) returned.
pub(crate) fn split(span: Span, max_groups: u32, params: &mut Vec<Params>) -> Vec<(usize, u32)> {
    let per_group = span.per_group.max(1);
    let per = max_groups.max(1) as u64 * per_group as u64;
    let mut out = Vec::new();
    let mut done = 0u64;
    while done < span.count as u64 {
        let this = (span.count as u64 - done).min(per) as u32;
        out.push((params.len(), this.div_ceil(per_group)));
        params.push(Params {
            first: span.first + done as u32,
            count: this,
            budget: span.budget,
            flags: span.flags,
        });
        done += this as u64;
    }
    out
}

/// Bind groups and workgroup counts of a stage's dispatches.
pub(crate) type Ranges = Vec<(wgpu::BindGroup, u32)>;

impl GpuContext {
    /// A command encoder.
    pub(crate) fn encoder(&self, label: &str) -> wgpu::CommandEncoder {
        self.device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(label) })
    }

    /// Bind groups for dispatches over `span` in ranges of at most
    /// `max_groups` workgroups (the per-dimension limit), each range with
    /// its own Params uniform; `bind` makes the bind group for a Params
    /// buffer. Returns (bind group, workgroups) per range.
    pub(crate) fn ranges(
        &self,
        span: Span,
        max_groups: u32,
        bind: &dyn Fn(&wgpu::Buffer) -> wgpu::BindGroup,
    ) -> Ranges {
        let mut params = Vec::new();
        split(span, max_groups, &mut params)
            .into_iter()
            .map(|(at, groups)| {
                // Params: which slice of the table this dispatch covers.
                let ub = self
                    .device
                    .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                        label: Some("params"),
                        contents: bytemuck::bytes_of(&params[at]),
                        usage: wgpu::BufferUsages::UNIFORM,
                    });
                (bind(&ub), groups)
            })
            .collect()
    }

    /// Records one dispatch of `stage` per range.
    pub(crate) fn record(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        stage: &Stage,
        ranges: &[(wgpu::BindGroup, u32)],
    ) {
        for (bg, groups) in ranges {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("dispatch"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&stage.pipeline);
            pass.set_bind_group(0, bg, &[]);
            pass.dispatch_workgroups(*groups, 1, 1);
        }
    }

    /// Records dispatches of `stage` over items 0..count, one per
    /// invocation, with Params at binding 0 and `buffers` at the stage's
    /// other bindings, in order.
    pub(crate) fn dispatch(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        stage: &Stage,
        count: u32,
        max_groups: u32,
        buffers: &[&wgpu::Buffer],
    ) {
        let r = self.ranges(Span::items(0, count), max_groups, &|params| {
            let all: Vec<&wgpu::Buffer> = std::iter::once(params)
                .chain(buffers.iter().copied())
                .collect();
            stage.bind(self, &all)
        });
        self.record(encoder, stage, &r);
    }
}
