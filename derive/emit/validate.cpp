#include "emit/validate.hpp"

#include "core/algebra.hpp"
#include "core/named_constants.hpp"
#include "core/powers_of_two.hpp"
#include "print/printer.hpp"

#include <algorithm>
#include <exception>
#include <set>
#include <utility>

namespace billiards::derive {

using GiNaC::ex;
using GiNaC::lst;

namespace {

// Where a guard stands: step index, guard index.
using GuardAt = std::pair<std::size_t, std::size_t>;

class Validation {
 public:
  Validation(const Kernel& kernel, const std::vector<Claim>& claims) : kernel_(kernel), claims_(claims) {}

  std::vector<KernelProblem> run() {
    if (!symbols_are_known()) return problems_;
    if (!cited_claims_verified()) return problems_;
    const Claim* target = find_claim(kernel_.equals);
    if (target == nullptr) {
      fail(kernel_.equals, "the kernel names no claim its outputs equal");
      return problems_;
    }
    target_ = target;
    check_main_branch();
    check_same_value_groups();
    check_piecewise_guards();
    check_unreachable_guards();
    check_overridden_guards();
    return problems_;
  }

 private:
  void fail(const std::string& claim, const std::string& reason) {
    problems_.push_back({kernel_.name, claim, reason});
  }

  const Claim* find_claim(const std::string& id) const {
    for (const Claim& claim : claims_) {
      if (claim.id == id) return &claim;
    }
    return nullptr;
  }

  // ---- symbols ----------------------------------------------------------------------------------
  bool symbols_are_known() {
    std::set<ex, GiNaC::ex_is_less> known(kernel_.parameters.begin(), kernel_.parameters.end());
    const auto unknown_in = [&](const ex& e, const std::string& where) {
      for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (GiNaC::is_a<GiNaC::symbol>(*it) && !known.count(*it) && !is_named_constant(*it)) {
          fail("", where + " reads " + GiNaC::ex_to<GiNaC::symbol>(*it).get_name() +
                       ", which is no parameter, earlier step or named constant");
          return true;
        }
      }
      return false;
    };
    bool ok = true;
    for (const KernelStep& step : kernel_.steps) {
      const std::string where = "step " + step.name.get_name();
      if (known.count(step.name)) {
        fail("", where + " reuses a name");
        ok = false;
      }
      ok = !unknown_in(step.expression, where) && ok;
      known.insert(step.name);  // a guard may read its own step's usual value
      for (const Guard& guard : step.guards) {
        ok = !unknown_in(guard.condition, where + "'s guard condition") && ok;
        ok = !unknown_in(guard.alternative, where + "'s guard alternative") && ok;
      }
    }
    for (const ex& output : kernel_.outputs) ok = !unknown_in(output, "an output") && ok;
    return ok;
  }

  bool cited_claims_verified() {
    bool ok = true;
    for (const std::string& id : cited_claims(kernel_)) {
      const Claim* claim = find_claim(id);
      if (claim == nullptr) {
        fail(id, "cites a claim the derivation does not record");
        ok = false;
      } else if (claim->verdict != Verdict::verified) {
        fail(id, "cites a claim that is " + to_string(claim->verdict) + ", not verified");
        ok = false;
      }
    }
    return ok;
  }

  // ---- values of a branch ----------------------------------------------------------------------
  struct Branch {
    std::set<GuardAt> taken;
    std::vector<ex> facts;  // relationals in the parameters that hold on this branch
  };

  // Every step's value on `branch`, in the parameters.
  GiNaC::exmap step_values(const Branch& branch) const {
    GiNaC::exmap values;
    for (std::size_t i = 0; i < kernel_.steps.size(); ++i) {
      const KernelStep& step = kernel_.steps[i];
      const ex usual = step.expression.subs(values);
      ex value = usual;
      for (std::size_t j = 0; j < step.guards.size(); ++j) {
        if (branch.taken.count({i, j}))
          value = guard_in_parameters(values, i, step.guards[j].alternative, usual);
      }
      values[step.name] = value;
    }
    return values;
  }

  // A guard's expression (its condition or alternative) in the parameters: the step's own name is its
  // usual value.
  ex guard_in_parameters(const GiNaC::exmap& earlier, std::size_t step, const ex& e, const ex& usual) const {
    GiNaC::exmap with_self = earlier;
    with_self[kernel_.steps[step].name] = usual;
    return e.subs(with_self);
  }

  // The condition of guard `at` in the parameters.
  ex condition_of(GuardAt at) const {
    GiNaC::exmap earlier;
    for (std::size_t i = 0; i < at.first; ++i) {
      earlier[kernel_.steps[i].name] = kernel_.steps[i].expression.subs(earlier);
    }
    const KernelStep& step = kernel_.steps[at.first];
    return guard_in_parameters(earlier, at.first, step.guards[at.second].condition,
                               step.expression.subs(earlier));
  }

  std::vector<GuardAt> all_guards() const {
    std::vector<GuardAt> guards;
    for (std::size_t i = 0; i < kernel_.steps.size(); ++i) {
      for (std::size_t j = 0; j < kernel_.steps[i].guards.size(); ++j) guards.emplace_back(i, j);
    }
    return guards;
  }

  // ---- comparison -------------------------------------------------------------------------------
  // An expression made comparable: in the claims' terms, every scaling by 2^k resolved for any k,
  // square roots of perfect squares taken, |…| resolved by the branch's facts and every remaining |…|
  // oriented alike.
  ex comparable(const ex& e, const std::vector<ex>& facts) const {
    ex out = take_square_roots(expand_radicands(resolve_powers_of_two(e.subs(kernel_.in_claim_terms))));
    for (const ex& fact : facts) {
      const ex in_terms = fact.subs(kernel_.in_claim_terms);
      if (!GiNaC::is_a<GiNaC::relational>(in_terms)) continue;
      const bool negative = in_terms.info(GiNaC::info_flags::relation_less) ||
                            in_terms.info(GiNaC::info_flags::relation_less_or_equal);
      const bool positive = in_terms.info(GiNaC::info_flags::relation_greater) ||
                            in_terms.info(GiNaC::info_flags::relation_greater_or_equal);
      if (!negative && !positive) continue;
      out = resolve_absolute_values(out, in_terms.lhs() - in_terms.rhs(), negative ? -1 : +1);
    }
    return orient_absolute_values(out);
  }

  // Every radicand expanded, so that one quantity written two ways (b² − a c and (w·w) r² − |p × w|²
  // in components) is one expression under the root.
  static ex expand_radicands(const ex& e) {
    if (GiNaC::is_a<GiNaC::power>(e) && !e.op(1).info(GiNaC::info_flags::integer)) {
      return GiNaC::pow(expand_radicands(e.op(0)).expand(), e.op(1));
    }
    struct map_radicands : GiNaC::map_function {
      ex operator()(const ex& operand) override { return expand_radicands(operand); }
    } recurse;
    return e.map(recurse);
  }

  static ex take_square_roots(const ex& e) {
    if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).is_equal(GiNaC::numeric(1, 2))) {
      const ex root = square_root_of_perfect_square(take_square_roots(e.op(0)));
      return root;
    }
    struct map_roots : GiNaC::map_function {
      ex operator()(const ex& operand) override { return take_square_roots(operand); }
    } recurse;
    return e.map(recurse);
  }

  // |a| and |−a| alike: the argument normalised, with the sign under which it prints first.
  static ex orient_absolute_values(const ex& e) {
    if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs") {
      const ex argument = GiNaC::normal(orient_absolute_values(e.op(0)));
      const ex negated = GiNaC::normal(-argument);
      return GiNaC::abs(print(negated, Notation::text) < print(argument, Notation::text) ? negated
                                                                                         : argument);
    }
    struct map_abs : GiNaC::map_function {
      ex operator()(const ex& operand) override { return orient_absolute_values(operand); }
    } recurse;
    return e.map(recurse);
  }

  lst target_outputs() const {
    if (GiNaC::is_a<lst>(target_->derived_expression)) return GiNaC::ex_to<lst>(target_->derived_expression);
    return lst{target_->derived_expression};
  }

  // Whether the outputs on `branch` equal the target claim's derived expression; the residual when not.
  bool outputs_equal_target(const Branch& branch, std::string& residual) const {
    const GiNaC::exmap values = step_values(branch);
    lst ours, theirs;
    const lst target = target_outputs();
    if (target.nops() != kernel_.outputs.size()) {
      residual = std::to_string(kernel_.outputs.size()) + " outputs against " +
                 std::to_string(target.nops()) + " in the claim";
      return false;
    }
    for (std::size_t i = 0; i < kernel_.outputs.size(); ++i) {
      ours.append(comparable(kernel_.outputs[i].subs(values), branch.facts));
      theirs.append(comparable(target.op(i), branch.facts));
    }
    Claim comparison;
    comparison.id = "kernel." + kernel_.name;
    comparison.comparison = Comparison::identity;
    comparison.paper_expression = theirs;
    comparison.derived_expression = ours;
    comparison.constraints = target_->constraints;
    check(comparison);
    if (comparison.verdict == Verdict::verified) return true;
    residual = comparison.failure.empty() ? print(comparison.residual, Notation::text) : comparison.failure;
    return false;
  }

  static ex negation(const ex& condition) {
    using GiNaC::relational;
    const ex l = condition.lhs(), r = condition.rhs();
    if (condition.info(GiNaC::info_flags::relation_less))
      return relational(l, r, relational::greater_or_equal);
    if (condition.info(GiNaC::info_flags::relation_less_or_equal))
      return relational(l, r, relational::greater);
    if (condition.info(GiNaC::info_flags::relation_greater))
      return relational(l, r, relational::less_or_equal);
    if (condition.info(GiNaC::info_flags::relation_greater_or_equal))
      return relational(l, r, relational::less);
    if (condition.info(GiNaC::info_flags::relation_equal)) return relational(l, r, relational::not_equal);
    return relational(l, r, relational::equal);
  }

  // The facts on a branch that takes `taken`: their conditions hold, every other guard's does not,
  // except guards before a taken one in the same step (a later guard wins, whatever an earlier said).
  Branch branch_taking(const std::set<GuardAt>& taken) const {
    Branch branch{taken, {}};
    for (const GuardAt& at : all_guards()) {
      if (taken.count(at)) {
        branch.facts.push_back(condition_of(at));
        continue;
      }
      bool overridden = false;
      for (const GuardAt& t : taken) overridden |= t.first == at.first && at.second < t.second;
      if (!overridden) branch.facts.push_back(negation(condition_of(at)));
    }
    return branch;
  }

  void check_main_branch() {
    std::string residual;
    if (!outputs_equal_target(branch_taking({}), residual)) {
      fail(kernel_.equals, "its outputs differ from the claim's derived expression by " + residual);
    }
  }

  void check_same_value_groups() {
    std::vector<std::pair<std::string, std::set<GuardAt>>> groups;
    for (const GuardAt& at : all_guards()) {
      const Guard& guard = kernel_.steps[at.first].guards[at.second];
      if (guard.kind != Guard::Kind::same_value) continue;
      const std::string key = print(guard.condition, Notation::text);
      auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == key; });
      if (group == groups.end()) {
        groups.push_back({key, {}});
        group = groups.end() - 1;
      }
      group->second.insert(at);
    }
    for (const auto& [condition, taken] : groups) {
      std::string residual;
      if (!outputs_equal_target(branch_taking(taken), residual)) {
        fail(kernel_.equals, "under its guard " + condition +
                                 " the outputs differ from the claim's derived "
                                 "expression by " +
                                 residual);
      }
    }
  }

  // (lhs − rhs, operator) of a relational, for comparing conditions up to rearrangement.
  static bool same_condition(const ex& a, const ex& b) {
    if (!GiNaC::is_a<GiNaC::relational>(a) || !GiNaC::is_a<GiNaC::relational>(b)) return false;
    const ex da = a.lhs() - a.rhs(), db = b.lhs() - b.rhs();
    using GiNaC::info_flags;
    const unsigned operators[] = {info_flags::relation_equal,   info_flags::relation_not_equal,
                                  info_flags::relation_less,    info_flags::relation_less_or_equal,
                                  info_flags::relation_greater, info_flags::relation_greater_or_equal};
    const unsigned mirrored[] = {info_flags::relation_equal,   info_flags::relation_not_equal,
                                 info_flags::relation_greater, info_flags::relation_greater_or_equal,
                                 info_flags::relation_less,    info_flags::relation_less_or_equal};
    for (std::size_t k = 0; k < 6; ++k) {
      if (!a.info(operators[k])) continue;
      if (b.info(operators[k]) && GiNaC::normal(da - db).is_zero()) return true;
      if (b.info(mirrored[k]) && GiNaC::normal(da + db).is_zero()) return true;
    }
    return false;
  }

  bool same_conditions(const Case& stated, const std::vector<ex>& conditions) const {
    if (stated.conditions.nops() != conditions.size()) return false;
    for (const ex& condition : conditions) {
      const ex ours = condition.subs(kernel_.in_claim_terms);
      bool found = false;
      for (const ex& theirs : stated.conditions)
        found |= same_condition(ours, theirs.subs(kernel_.in_claim_terms));
      if (!found) return false;
    }
    return true;
  }
  // A case with one value: the guarded step's value is it. A case with a list of values: on the branch
  // that takes every piecewise guard of the same condition, each output is the value in its place.
  bool matches_case(const Case& stated, const std::vector<ex>& conditions, GuardAt at,
                    const ex& value) const {
    if (!same_conditions(stated, conditions)) return false;
    if (!GiNaC::is_a<lst>(stated.value)) {
      return GiNaC::normal(comparable(value, {}) - comparable(stated.value, {})).is_zero();
    }
    const lst& values = GiNaC::ex_to<lst>(stated.value);
    if (values.nops() != kernel_.outputs.size()) return false;
    std::set<GuardAt> taken;
    for (const GuardAt& other : all_guards()) {
      const Guard& guard = kernel_.steps[other.first].guards[other.second];
      if (guard.kind == Guard::Kind::piecewise && same_condition(condition_of(other), condition_of(at)))
        taken.insert(other);
    }
    const Branch branch = branch_taking(taken);
    const GiNaC::exmap steps = step_values(branch);
    for (std::size_t i = 0; i < values.nops(); ++i) {
      if (!GiNaC::normal(comparable(kernel_.outputs[i].subs(steps), branch.facts) -
                         comparable(values.op(i), branch.facts))
               .is_zero())
        return false;
    }
    return true;
  }

  void check_piecewise_guards() {
    for (const GuardAt& at : all_guards()) {
      const KernelStep& step = kernel_.steps[at.first];
      const Guard& guard = step.guards[at.second];
      if (guard.kind != Guard::Kind::piecewise) continue;
      const Branch branch = branch_taking({at});
      std::string residual;
      if (outputs_equal_target(branch, residual)) continue;
      // Not the same value: the condition, with the later guards of its step not taken, and the step's
      // value must be a case its claim states.
      std::vector<ex> conditions{condition_of(at)};
      for (std::size_t j = at.second + 1; j < step.guards.size(); ++j) {
        conditions.push_back(negation(condition_of({at.first, j})));
      }
      const ex value = step_values(branch).at(step.name);
      const Claim* claim = find_claim(guard.claim);
      bool stated = false;
      if (claim != nullptr) {
        for (const Case& c : claim->cases) stated |= matches_case(c, conditions, at, value);
      }
      if (!stated) {
        fail(guard.claim, "its guard " + print(guard.condition, Notation::text) + " on step " +
                              step.name.get_name() +
                              " is no case the claim states, and the outputs there differ "
                              "from " +
                              kernel_.equals + " by " + residual);
      }
    }
  }

  void check_unreachable_guards() {
    for (const GuardAt& at : all_guards()) {
      const Guard& guard = kernel_.steps[at.first].guards[at.second];
      if (guard.kind != Guard::Kind::unreachable) continue;
      const ex condition = condition_of(at);
      const Claim* claim = find_claim(guard.claim);
      const bool is_less =
          GiNaC::is_a<GiNaC::relational>(condition) && condition.info(GiNaC::info_flags::relation_less);
      const bool proven = is_less && claim != nullptr && claim->comparison == Comparison::nonnegative &&
                          GiNaC::normal(comparable(condition.lhs() - condition.rhs(), {}) -
                                        comparable(claim->derived_expression, {}))
                              .is_zero();
      if (!proven) {
        fail(guard.claim, "its guard " + print(guard.condition, Notation::text) +
                              " is not `x < 0` for the x the claim shows to be ≥ 0");
      }
    }
  }

  // An overridden guard changes no output: taken with the piecewise guards of its condition, the
  // outputs equal those of the same branch without it, whichever of the other guards are taken too.
  void check_overridden_guards() {
    for (const GuardAt& at : all_guards()) {
      const Guard& guard = kernel_.steps[at.first].guards[at.second];
      if (guard.kind != Guard::Kind::overridden) continue;
      const std::string where = "its guard " + print(guard.condition, Notation::text) + " on step " +
                                kernel_.steps[at.first].name.get_name();
      std::set<GuardAt> overriding;
      std::vector<GuardAt> others;
      for (const GuardAt& other : all_guards()) {
        if (other == at) continue;
        const Guard& g = kernel_.steps[other.first].guards[other.second];
        if (g.kind == Guard::Kind::piecewise && same_condition(condition_of(other), condition_of(at))) {
          overriding.insert(other);
        } else {
          others.push_back(other);
        }
      }
      if (overriding.empty()) {
        fail(guard.claim, where + " is overridden by no piecewise guard of the same condition");
        continue;
      }
      constexpr std::size_t most_others = 10;  // 2^10 branches
      if (others.size() > most_others) {
        fail(guard.claim, where + " has too many other guards to try every combination");
        continue;
      }
      for (std::size_t mask = 0; mask < (std::size_t(1) << others.size()); ++mask) {
        std::set<GuardAt> taken = overriding;
        for (std::size_t k = 0; k < others.size(); ++k) {
          if (mask & (std::size_t(1) << k)) taken.insert(others[k]);
        }
        const GiNaC::exmap without = step_values(branch_taking(taken));
        taken.insert(at);
        const GiNaC::exmap with = step_values(branch_taking(taken));
        bool same = true;
        for (const ex& output : kernel_.outputs) {
          same = same && GiNaC::normal(output.subs(with) - output.subs(without)).is_zero();
        }
        if (!same) {
          fail(guard.claim, where +
                                " changes an output where it is taken: no piecewise guard of its "
                                "condition overrides every output that reads it");
          break;
        }
      }
    }
  }

  const Kernel& kernel_;
  const std::vector<Claim>& claims_;
  const Claim* target_ = nullptr;
  std::vector<KernelProblem> problems_;
};

}  // namespace

std::vector<KernelProblem> validate_kernel(const Kernel& kernel, const std::vector<Claim>& claims) {
  try {
    return Validation(kernel, claims).run();
  } catch (const std::exception& error) {
    return {{kernel.name, kernel.equals,
             std::string("the validation could not be carried out: ") + error.what()}};
  }
}

namespace {

bool same_list(const std::vector<ex>& a, const std::vector<ex>& b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](const ex& x, const ex& y) { return x.is_equal(y); });
}

bool same_map(const GiNaC::exmap& a, const GiNaC::exmap& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const auto& x, const auto& y) {
           return x.first.is_equal(y.first) && x.second.is_equal(y.second);
         });
}

// A fast path's problems: it must name a kernel printed before it with the same parameters, the same
// claim and the same claim terms, whose domain is the path's conditions (so the accuracy tool measures
// it where it is taken); the conditions are relationals in the parameters and named constants; and one
// predicate name stands for one set of conditions.
std::vector<KernelProblem> fast_path_problems(const std::vector<Kernel>& kernels, std::size_t at) {
  const Kernel& kernel = kernels[at];
  const FastPath& path = *kernel.fast_path;
  std::vector<KernelProblem> problems;
  const auto fail = [&](const std::string& reason) {
    problems.push_back({kernel.name, path.claim, "its fast path " + reason});
  };
  if (path.predicate.empty()) fail("has no predicate name");
  if (path.conditions.empty()) fail("has no conditions");
  for (const ex& condition : path.conditions) {
    if (!GiNaC::is_a<GiNaC::relational>(condition)) {
      fail("has the condition " + print(condition, Notation::text) + ", which is no relational");
      continue;
    }
    for (GiNaC::const_preorder_iterator it = condition.preorder_begin(); it != condition.preorder_end();
         ++it) {
      const bool known = std::any_of(kernel.parameters.begin(), kernel.parameters.end(),
                                     [&](const ex& p) { return p.is_equal(*it); });
      if (GiNaC::is_a<GiNaC::symbol>(*it) && !known && !is_named_constant(*it)) {
        fail("reads " + GiNaC::ex_to<GiNaC::symbol>(*it).get_name() +
             ", which is no parameter or named constant");
      }
    }
  }
  for (std::size_t i = 0; i < kernels.size(); ++i) {
    const Kernel& other = kernels[i];
    if (i != at && other.fast_path && other.fast_path->predicate == path.predicate &&
        !same_list(other.fast_path->conditions, path.conditions)) {
      fail("names the predicate " + path.predicate + ", which " + other.name +
           "'s fast path defines otherwise");
    }
  }
  const auto taken = std::find_if(kernels.begin(), kernels.begin() + static_cast<std::ptrdiff_t>(at),
                                  [&](const Kernel& k) { return k.name == path.kernel; });
  if (taken == kernels.begin() + static_cast<std::ptrdiff_t>(at)) {
    fail("takes " + path.kernel + ", which is no kernel printed before it");
    return problems;
  }
  if (!same_list(taken->parameters, kernel.parameters))
    fail("takes " + path.kernel + ", whose parameters differ");
  if (taken->equals != kernel.equals) {
    fail("takes " + path.kernel + ", which is proven equal to " + taken->equals + ", not " + kernel.equals);
  }
  if (!same_map(taken->in_claim_terms, kernel.in_claim_terms)) {
    fail("takes " + path.kernel + ", whose parameters stand for other terms of the claim");
  }
  if (!same_list(taken->domain, path.conditions)) {
    fail("takes " + path.kernel + ", whose domain is not the path's conditions");
  }
  return problems;
}

}  // namespace

std::vector<KernelProblem> validate_kernels(const std::vector<Kernel>& kernels,
                                            const std::vector<Claim>& claims) {
  std::vector<KernelProblem> problems;
  for (std::size_t i = 0; i < kernels.size(); ++i) {
    std::vector<KernelProblem> found = validate_kernel(kernels[i], claims);
    for (std::size_t j = 0; j < kernels.size(); ++j) {
      const Kernel &kernel = kernels[i], &other = kernels[j];
      if (j < i && other.name == kernel.name) {
        found.push_back({kernel.name, kernel.equals, "has the name of a kernel printed before it"});
      }
      if (j != i && other.fast_path && full_form_name(other) == kernel.name) {
        found.push_back({kernel.name, kernel.equals,
                         "has the name of the function that holds " + other.name + "'s full form"});
      }
      if (j != i && kernel.fast_path && full_form_name(kernel) == other.name) {
        found.push_back({kernel.name, kernel.equals,
                         "would print its full form as " + full_form_name(kernel) +
                             ", which is the name of another kernel"});
      }
    }
    if (kernels[i].fast_path) {
      const std::vector<KernelProblem> path = fast_path_problems(kernels, i);
      found.insert(found.end(), path.begin(), path.end());
    }
    problems.insert(problems.end(), found.begin(), found.end());
  }
  return problems;
}

}  // namespace billiards::derive
