// convexloc (internal) — the members of detail::SinkQueries (see
// convexloc/detail/sink_queries.hpp). A locator's source file includes this after its run<Sink>
// and instantiates the class once; Sinks<Trace> names the dimension's two sinks.
#pragma once

#include <span>

#include "convexloc/detail/sink_queries.hpp"
#include "detail/batch_loop.hpp"

namespace convexloc::detail {

// the sink that records nothing (None) and the one that records into a Trace (Record)
template <class Trace>
struct Sinks;

template <class D, class P, class T>
Location SinkQueries<D, P, T>::locate(P p) const noexcept {
  typename Sinks<T>::None sink;
  return self().run(p, sink);
}

template <class D, class P, class T>
void SinkQueries<D, P, T>::locate(std::span<const P> points,
                                  std::span<Location> out) const noexcept {
  locateEach(*this, points, out);
}

template <class D, class P, class T>
T SinkQueries<D, P, T>::trace(P p) const {
  T t;
  t.method = D::kMethod;
  typename Sinks<T>::Record sink{t};
  t.result = self().run(p, sink);
  if constexpr (requires { self().completeTrace(t); }) self().completeTrace(t);
  return t;
}

}  // namespace convexloc::detail
