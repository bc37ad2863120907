// A render's estimate of its own error from the film's moments (image/error_estimate.h says
// what it estimates and how far it is trusted).
#pragma once
#include <array>

#include "image/error_estimate.h"
#include "render/film_readback.h"
#include "render/samplers/samplers.h"

namespace wf {

// With one sequence, `sampler` says whether the samples were independent (the estimate
// measures their variance) or correlated, as every other sampler's are (then it bounds the
// error from above). With error replicates (film.replicates > 1) the spread of the replicates'
// means measures the error whatever the sampler.
ErrorEstimate estimateFilmError(const FilmMoments& film, SamplerKind sampler);

// The same film's estimate as if its samples were independent (replicates ignored): what the
// variance of the samples alone says, against which --target-error measures a sampler's gain.
ErrorEstimate estimateIndependentFilmError(const FilmMoments& film);

// Per channel, the variance of pixel `pixel`'s mean estimated from the spread of its
// replicates' means (film.replicates > 1): sum over r of (n_r / n)^2 (m_r - m)^2 K / (K - 1),
// without bias when the replicates are independent and equally long, as interleaving keeps
// them to within a sample. False when some replicate has no sample.
bool replicateVarianceOfMean(const FilmMoments& film, size_t pixel, std::array<double, 3>& out);

} // namespace wf
