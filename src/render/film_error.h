// A render's estimate of its own error from the film's moments (image/error_estimate.h says
// what it estimates and how far it is trusted).
#pragma once
#include "image/error_estimate.h"
#include "render/film_readback.h"
#include "render/samplers/samplers.h"

namespace wf {

// `sampler` says whether the samples were independent (the estimate measures their variance)
// or correlated, as every other sampler's are (then it bounds the error from above).
ErrorEstimate estimateFilmError(const FilmMoments& film, SamplerKind sampler);

} // namespace wf
