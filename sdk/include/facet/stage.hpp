#pragma once
// The base class of every stage, and the headers a stage author needs.
//
//   class MedianFilter final : public facet::Stage {
//    public:
//     static facet::StageSpec spec();                    // static contract, see stage_spec.hpp
//     explicit MedianFilter(const facet::Params& params);
//     void process(facet::ProcessContext& ctx) override;
//   };
//
// Lifecycle: constructed from validated parameters → open() → process() once per frame →
// close(). Throw facet::StageError for problems the user can fix (bad file, bad input).

#include <string>

#include "facet/context.hpp"
#include "facet/error.hpp"
#include "facet/packet.hpp"
#include "facet/param.hpp"
#include "facet/stage_spec.hpp"

namespace facet {

struct OpenContext {
  std::string node_id;
};

class Stage {
 public:
  virtual ~Stage() = default;
  Stage() = default;
  Stage(const Stage&) = delete;
  Stage& operator=(const Stage&) = delete;

  // Acquire resources (files, devices). Called once before the first frame.
  virtual void open(const OpenContext& /*ctx*/) {}
  // Read inputs, write every output (an output left unset is empty for this frame).
  virtual void process(ProcessContext& ctx) = 0;
  // Release resources and flush. Called once after the last frame, also after an error.
  virtual void close() {}
};

}  // namespace facet
