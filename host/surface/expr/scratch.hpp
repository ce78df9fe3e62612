#pragma once
// Per-thread scratch space for evaluation: the node values of one evaluation, reused so that
// hot loops (cell bounds, the reference intersector) allocate nothing.
#include <vector>

namespace lancer::surface {

template <class T>
T* scratch_values(std::size_t count) {
    thread_local std::vector<T> values;
    if (values.size() < count) values.resize(count);
    return values.data();
}

}  // namespace lancer::surface
