#include "surface/expr/program.hpp"

#include <bit>
#include <cmath>
#include <map>
#include <tuple>

#include "surface/expr/evaluate_nodes.hpp"
#include "surface/expr/gpu_float.hpp"
#include "surface/expr/scratch.hpp"

namespace lancer::surface {
namespace {

// Two nodes with the same key compute the same value (operands are already deduplicated).
using NodeKey = std::tuple<Op, int, int, std::uint64_t>;

class ProgramBuilder {
public:
    int add(const Expr& expr, int origin) {
        origin_ = origin;
        std::vector<int> map(expr.nodes.size());
        for (std::size_t i = 0; i < expr.nodes.size(); ++i) map[i] = add_node(expr.nodes[i], map);
        return expr.nodes.empty() ? add_constant(0.0, 0) : map.back();
    }

    Program finish(std::vector<int> outputs) {
        // Keep only what the outputs need (folding leaves the folded operands behind).
        std::vector<char> live(nodes_.size(), 0);
        for (int o : outputs) live[o] = 1;
        for (int i = static_cast<int>(nodes_.size()) - 1; i >= 0; --i) {
            if (!live[i]) continue;
            if (nodes_[i].a >= 0) live[nodes_[i].a] = 1;
            if (nodes_[i].b >= 0) live[nodes_[i].b] = 1;
        }
        Program program;
        std::vector<int> renumber(nodes_.size(), -1);
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            if (!live[i]) continue;
            Node n = nodes_[i];
            if (n.a >= 0) n.a = renumber[n.a];
            if (n.b >= 0) n.b = renumber[n.b];
            renumber[i] = static_cast<int>(program.nodes.size());
            program.nodes.push_back(n);
            program.origins.push_back(origins_[i]);
        }
        for (int o : outputs) program.outputs.push_back(renumber[o]);
        return program;
    }

private:
    int add_node(Node n, const std::vector<int>& map) {
        if (n.a >= 0) n.a = map[n.a];
        // The exponent of PowInt/PowConst is already in `value`.
        n.b = (n.op == Op::PowInt || n.op == Op::PowConst || n.b < 0) ? -1 : map[n.b];
        if (n.op != Op::Variable && n.op != Op::Constant && is_constant(n.a) && is_constant(n.b)) {
            double operands[2] = {n.a >= 0 ? nodes_[n.a].value : 0.0, n.b >= 0 ? nodes_[n.b].value : 0.0};
            Node local = n;
            local.a = n.a >= 0 ? 0 : -1;
            local.b = n.b >= 0 ? 1 : -1;
            double folded = apply_node<double>(local, operands, nullptr);
            // A non-finite constant stays an operation, so that intervals still see its domain.
            if (std::isfinite(folded)) return add_constant(folded, n.column);
        }
        return intern(n);
    }

    bool is_constant(int index) const { return index < 0 || nodes_[index].op == Op::Constant; }

    int add_constant(double value, int column) { return intern({Op::Constant, -1, -1, value, column}); }

    int intern(const Node& n) {
        NodeKey key{n.op, n.a, n.b, std::bit_cast<std::uint64_t>(n.value)};
        auto [it, inserted] = index_.try_emplace(key, static_cast<int>(nodes_.size()));
        if (inserted) {
            nodes_.push_back(n);
            origins_.push_back(origin_);
        }
        return it->second;
    }

    std::vector<Node> nodes_;
    std::vector<int> origins_;
    int origin_ = 0;
    std::map<NodeKey, int> index_;
};

}  // namespace

Program compile_program(std::span<const Expr* const> expressions) {
    ProgramBuilder builder;
    std::vector<int> outputs;
    for (const Expr* e : expressions) outputs.push_back(builder.add(*e, static_cast<int>(outputs.size())));
    return builder.finish(std::move(outputs));
}

int count_operations(const Program& program) {
    int count = 0;
    for (const Node& n : program.nodes) count += n.op != Op::Constant && n.op != Op::Variable;
    return count;
}

template <class T>
const T* evaluate_all_nodes(const Program& program, std::span<const T> variables) {
    T* values = scratch_values<T>(program.nodes.size());
    evaluate_nodes(program.nodes.data(), static_cast<int>(program.nodes.size()), variables.data(), values);
    return values;
}

template <class T>
const T* evaluate_all_nodes(const Program& program, const T& u, const T& v) {
    const T uv[] = {u, v};
    return evaluate_all_nodes<T>(program, std::span<const T>(uv));
}

template <class T>
void evaluate_program(const Program& program, std::span<const T> variables, T* out) {
    const T* values = evaluate_all_nodes<T>(program, variables);
    for (std::size_t i = 0; i < program.outputs.size(); ++i) out[i] = values[program.outputs[i]];
}

template <class T>
void evaluate_program(const Program& program, const T& u, const T& v, T* out) {
    const T uv[] = {u, v};
    evaluate_program<T>(program, std::span<const T>(uv), out);
}

namespace {

// Whether node n is defined and smooth for all operand values in its operands' intervals.
bool proved_smooth(const Node& n, const Dual<Interval>* values) {
    const Interval a = n.a >= 0 ? values[n.a].v : Interval();
    const Interval b = n.b >= 0 ? values[n.b].v : Interval();
    auto excludes_zero = [](const Interval& x) { return x.lo > 0.0 || x.hi < 0.0; };
    switch (n.op) {
        case Op::Div: return excludes_zero(b);
        case Op::PowInt: return n.value >= 0.0 || excludes_zero(a);
        case Op::PowConst: return n.value >= 1.0 ? a.lo >= 0.0 : a.lo > 0.0;
        case Op::Pow:
        case Op::Sqrt:
        case Op::Log:
        case Op::Log2:
        case Op::Log10: return a.lo > 0.0;
        case Op::Cbrt: return excludes_zero(a);
        case Op::Asin:
        case Op::Acos:
        case Op::Atanh: return a.lo > -1.0 && a.hi < 1.0;
        case Op::Acosh: return a.lo > 1.0;
        case Op::Atan2: return !(a.contains_zero() && b.lo <= 0.0);
        case Op::Hypot: return excludes_zero(a) || excludes_zero(b);
        default: return true;
    }
}

}  // namespace

bool evaluate_program_on_box(const Program& program, const Interval& u, const Interval& v, Dual<Interval>* out) {
    const Dual<Interval> uv[] = {Dual<Interval>::variable_u(u), Dual<Interval>::variable_v(v)};
    return evaluate_program_on_box(program, std::span<const Dual<Interval>>(uv), out);
}

bool evaluate_program_on_box(const Program& program, std::span<const Dual<Interval>> variables, Dual<Interval>* out) {
    const int count = static_cast<int>(program.nodes.size());
    Dual<Interval>* values = scratch_values<Dual<Interval>>(program.nodes.size());
    evaluate_nodes(program.nodes.data(), count, variables.data(), values);
    for (std::size_t i = 0; i < program.outputs.size(); ++i) out[i] = values[program.outputs[i]];
    for (int i = 0; i < count; ++i) {
        const Node& n = program.nodes[i];
        bool smooth = n.op == Op::Tan ? values[i].v.is_finite() : proved_smooth(n, values);
        if (!smooth) return false;
    }
    return true;
}

template void evaluate_program(const Program&, const double&, const double&, double*);
template void evaluate_program(const Program&, const Interval&, const Interval&, Interval*);
template void evaluate_program(const Program&, const Dual<double>&, const Dual<double>&, Dual<double>*);
template void evaluate_program(const Program&, const Dual<Interval>&, const Dual<Interval>&, Dual<Interval>*);
template void evaluate_program(const Program&, const Dual<Dual<Interval>>&, const Dual<Dual<Interval>>&,
                               Dual<Dual<Interval>>*);
template void evaluate_program(const Program&, std::span<const double>, double*);
template void evaluate_program(const Program&, std::span<const Interval>, Interval*);
template void evaluate_program(const Program&, std::span<const Dual<double>>, Dual<double>*);
template void evaluate_program(const Program&, std::span<const Dual<Interval>>, Dual<Interval>*);
template void evaluate_program(const Program&, const Dual<GpuFloat>&, const Dual<GpuFloat>&, Dual<GpuFloat>*);
template const double* evaluate_all_nodes(const Program&, const double&, const double&);
template const Interval* evaluate_all_nodes(const Program&, const Interval&, const Interval&);
template const Dual<double>* evaluate_all_nodes(const Program&, const Dual<double>&, const Dual<double>&);
template const Dual<GpuFloat>* evaluate_all_nodes(const Program&, const Dual<GpuFloat>&, const Dual<GpuFloat>&);
template const Dual<double>* evaluate_all_nodes(const Program&, std::span<const Dual<double>>);
template const Dual<GpuFloat>* evaluate_all_nodes(const Program&, std::span<const Dual<GpuFloat>>);

}  // namespace lancer::surface
