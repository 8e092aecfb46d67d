#include "label_source.h"

namespace pedtrack::render {

LabelSource::LabelSource(const std::string& path)
    : path_(path), reader_(std::make_unique<LabelFileReader>(path)) {
  kind_ = reader_->kind();
}

const LabelFrame* LabelSource::at(std::size_t index, std::size_t points) {
  if (have_ && current_.index > index) {  // going back: start over
    reader_ = std::make_unique<LabelFileReader>(path_);
    have_ = ended_ = false;
  }
  while (!ended_ && (!have_ || current_.index < index)) {
    if (reader_->next(next_)) {
      std::swap(current_, next_);
      have_ = true;
    } else {
      ended_ = true;  // current_ keeps the last frame
    }
  }
  if (!have_ || current_.index != index || current_.labels.size() != points) return nullptr;
  return &current_;
}

}  // namespace pedtrack::render
