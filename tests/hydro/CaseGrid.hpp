#pragma once
// Every combination of a test's parameter lists, one call each: keeps the loops of a parameter
// scan out of the test body, which then reads as the check it makes.
#include <vector>

namespace granwave::hydro::test {

template <class A, class B, class C, class Check>
void forEachCase(const std::vector<A>& as, const std::vector<B>& bs, const std::vector<C>& cs,
                 Check&& check) {
  for (const A& a : as)
    for (const B& b : bs)
      for (const C& c : cs) check(a, b, c);
}

template <class A, class B, class C, class D, class Check>
void forEachCase(const std::vector<A>& as, const std::vector<B>& bs, const std::vector<C>& cs,
                 const std::vector<D>& ds, Check&& check) {
  for (const A& a : as)
    for (const B& b : bs)
      for (const C& c : cs)
        for (const D& d : ds) check(a, b, c, d);
}

}  // namespace granwave::hydro::test
