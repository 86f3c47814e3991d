//===- CheckRegistrationFlow.cpp ------------------------------------------===//
//
// A guard is a region that may be skipped: an if branch, a switch body, the
// rest of a function after a return... A registration is safe when every
// guard around it is also around wash::start: then whenever the run starts,
// the registration ran (once, since loops, goto and recursion are rejected).
//
//===----------------------------------------------------------------------===//
#include "wash/translator/Frontend/CheckRegistrationFlow.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/ExprCXX.h"
#include "clang/AST/StmtCXX.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

using namespace clang;

namespace wash::tr {
namespace {

struct Guard {
  unsigned Parent; ///< 0: none.
  const char *What;
};

/// One walk of a function body (a call, as if inlined).
struct Frame {
  unsigned Parent; ///< 0: none (main).
  const FunctionDecl *Function;
  unsigned RestGuard = 0; ///< Guards the rest of the body after a return.
  bool UsesGoto = false;
  bool Recursive = false; ///< Calls itself, directly or not.
  unsigned FirstCall = 0; ///< Index of the first registration or start in it.
};

/// A registration or wash::start the walk reached.
struct Call {
  const CallExpr *E;
  std::string Name;
  bool IsStart;
  std::vector<unsigned> Guards; ///< Sorted: older (outer) guards first.
  unsigned Frame;
  bool InLoop;
};

/// Visit a statement; handle a call once its arguments are visited; mark
/// the rest of a body as guarded after a return; end a body.
enum class ItemKind { Visit, Call, Return, EndFrame };

struct Item {
  ItemKind Kind;
  const Stmt *S;
  unsigned Guard;
  unsigned Frame;
  bool InLoop;
};

static bool usesGoto(const Stmt *Body) {
  std::vector<const Stmt *> Work{Body};
  while (!Work.empty()) {
    const Stmt *S = Work.back();
    Work.pop_back();
    if (!S || isa<LambdaExpr>(S))
      continue;
    if (isa<GotoStmt, IndirectGotoStmt, LabelStmt>(S))
      return true;
    for (const Stmt *Child : S->children())
      Work.push_back(Child);
  }
  return false;
}

class FlowChecker {
public:
  FlowChecker(ProgramIndex &Index, Diagnoser &D)
      : Ctx(Index.context()), Index(Index), D(D), Walk(Index) {}

  void run(const FunctionDecl *Main) {
    enter(Main, /*Guard=*/0, /*Caller=*/0, /*InLoop=*/false);
    while (!Work.empty()) {
      Item I = Work.back();
      Work.pop_back();
      switch (I.Kind) {
      case ItemKind::Visit:
        visit(I);
        break;
      case ItemKind::Call:
        call(cast<CallExpr>(I.S), I);
        break;
      case ItemKind::Return:
        if (!Frames[I.Frame].RestGuard)
          Frames[I.Frame].RestGuard = newGuard(0, "after an early 'return'");
        break;
      case ItemKind::EndFrame:
        endFrame(I.Frame);
        break;
      }
    }
    checkAgainstStart();
  }

private:
  unsigned newGuard(unsigned Parent, const char *What) {
    Guards.push_back({Parent, What});
    return Guards.size() - 1;
  }

  void push(const Stmt *S, const Item &From, unsigned Guard) {
    if (S)
      Work.push_back({ItemKind::Visit, S, Guard, From.Frame, From.InLoop});
  }
  /// Children are pushed last first, so that they are visited in order.
  void pushInOrder(std::initializer_list<std::pair<const Stmt *, unsigned>> Children,
                   const Item &From) {
    for (auto It = std::rbegin(Children); It != std::rend(Children); ++It)
      push(It->first, From, It->second);
  }

  void enter(const FunctionDecl *FD, unsigned Guard, unsigned Caller, bool InLoop) {
    unsigned F = Frames.size();
    if (auto Entry = Walk.push(FD, F); Entry != CallWalk<unsigned>::Entry::Entered) {
      if (Entry == CallWalk<unsigned>::Entry::Recursive)
        Frames[*Walk.find(FD)].Recursive = true;
      else if (Index.firstOverrun()) // main is not all checked: never accept it so
        D.report(DiagId::ProgramTooComplex, FD->getLocation(), {std::to_string(Index.budget())});
      return;
    }
    Frames.push_back({Caller, FD->getCanonicalDecl()});
    Frames[F].UsesGoto = usesGoto(FD->getBody());
    Frames[F].FirstCall = Calls.size();
    Work.push_back({ItemKind::EndFrame, nullptr, 0, F, InLoop});
    Work.push_back({ItemKind::Visit, FD->getBody(), Guard, F, InLoop});
  }

  void visit(Item I) {
    const Stmt *S = I.S;
    if (isa<ForStmt, WhileStmt, DoStmt, CXXForRangeStmt>(S))
      I.InLoop = true;
    if (const auto *L = dyn_cast<LambdaExpr>(S)) {
      // The body runs when the lambda is called, and is walked then.
      std::vector<const Stmt *> Inits(L->capture_init_begin(), L->capture_init_end());
      for (auto It = Inits.rbegin(); It != Inits.rend(); ++It)
        push(*It, I, I.Guard);
      return;
    }
    if (const auto *If = dyn_cast<IfStmt>(S)) {
      unsigned Then = newGuard(I.Guard, "inside an 'if'");
      unsigned Else = newGuard(I.Guard, "inside an 'else'");
      bool Taken;
      if (If->isConstexpr() && If->getCond() &&
          If->getCond()->EvaluateAsBooleanCondition(Taken, Ctx)) {
        (Taken ? Then : Else) = I.Guard;
        (Taken ? Else : Then) = newGuard(I.Guard, "in a discarded 'if constexpr' branch");
      }
      return pushInOrder({{If->getInit(), I.Guard},
                          {If->getConditionVariableDeclStmt(), I.Guard},
                          {If->getCond(), I.Guard},
                          {If->getThen(), Then},
                          {If->getElse(), Else}},
                         I);
    }
    if (const auto *Sw = dyn_cast<SwitchStmt>(S))
      return pushInOrder({{Sw->getInit(), I.Guard},
                          {Sw->getConditionVariableDeclStmt(), I.Guard},
                          {Sw->getCond(), I.Guard},
                          {Sw->getBody(), newGuard(I.Guard, "inside a 'switch'")}},
                         I);
    if (const auto *C = dyn_cast<ConditionalOperator>(S))
      return pushInOrder({{C->getCond(), I.Guard},
                          {C->getTrueExpr(), newGuard(I.Guard, "in an operand of '?:'")},
                          {C->getFalseExpr(), newGuard(I.Guard, "in an operand of '?:'")}},
                         I);
    if (const auto *C = dyn_cast<BinaryConditionalOperator>(S))
      return pushInOrder({{C->getCommon(), I.Guard},
                          {C->getFalseExpr(), newGuard(I.Guard, "in an operand of '?:'")}},
                         I);
    if (const auto *B = dyn_cast<BinaryOperator>(S); B && B->isLogicalOp())
      return pushInOrder(
          {{B->getLHS(), I.Guard},
           {B->getRHS(), newGuard(I.Guard, B->getOpcode() == BO_LAnd ? "on the right of '&&'"
                                                                     : "on the right of '||'")}},
          I);
    if (const auto *T = dyn_cast<CXXTryStmt>(S)) {
      for (unsigned H = T->getNumHandlers(); H-- > 0;)
        push(T->getHandler(H), I, newGuard(I.Guard, "inside a 'catch' handler"));
      push(T->getTryBlock(), I, newGuard(I.Guard, "inside a 'try' block"));
      return;
    }
    if (isa<ReturnStmt, CoreturnStmt>(S))
      // After the returned value is computed, the rest of the body is guarded.
      Work.push_back({ItemKind::Return, nullptr, 0, I.Frame, I.InLoop});

    // The call itself after its callee and arguments, which run first.
    if (isa<CallExpr>(S))
      Work.push_back({ItemKind::Call, S, I.Guard, I.Frame, I.InLoop});
    std::vector<const Stmt *> Children(S->child_begin(), S->child_end());
    for (auto It = Children.rbegin(); It != Children.rend(); ++It)
      push(*It, I, I.Guard);
  }

  void call(const CallExpr *CE, const Item &I) {
    const FunctionDecl *FD = CE->getDirectCallee();
    if (!FD)
      return;
    if (const ApiCallInfo *Api = washCall(FD)) {
      bool IsStart = Api->Id == ApiCall::start;
      if (!IsStart && Api->Use != CallUse::MainOnce)
        return; // Settings may be conditional: the generated program makes them too.
      Calls.push_back({CE, Api->Name, IsStart, guardsOf(I.Guard, I.Frame), I.Frame, I.InLoop});
      if (inGotoFunction(I.Frame))
        reportCall(Calls.back(), "in a function that uses 'goto'");
      else if (IsStart && I.InLoop)
        reportCall(Calls.back(), "inside a loop");
      // A registration in a loop is reported by collectSimulation.
      return;
    }
    const FunctionDecl *Def = FD->getDefinition();
    if (!Def || !Def->hasBody() || !Index.isUserFunction(Def))
      return;
    enter(Def, I.Guard, I.Frame, I.InLoop);
  }

  std::vector<unsigned> guardsOf(unsigned Guard, unsigned F) const {
    std::vector<unsigned> Set;
    for (; Guard; Guard = Guards[Guard].Parent)
      Set.push_back(Guard);
    for (;; F = Frames[F].Parent) {
      if (Frames[F].RestGuard)
        Set.push_back(Frames[F].RestGuard);
      if (F == 0)
        break;
    }
    std::sort(Set.begin(), Set.end());
    return Set;
  }

  bool inGotoFunction(unsigned F) const {
    for (;; F = Frames[F].Parent) {
      if (Frames[F].UsesGoto)
        return true;
      if (F == 0)
        return false;
    }
  }

  void endFrame(unsigned F) {
    Walk.pop();
    if (!Frames[F].Recursive)
      return;
    std::string Why = "in '" + Frames[F].Function->getQualifiedNameAsString() +
                      "', which calls itself recursively";
    for (unsigned C = Frames[F].FirstCall; C < Calls.size(); ++C)
      reportCall(Calls[C], Why);
  }

  void reportCall(const Call &C, const std::string &Why) {
    if (C.IsStart)
      D.report(DiagId::StartRepeated, C.E->getBeginLoc(), {Why});
    else
      D.report(DiagId::RegistrationConditional, C.E->getBeginLoc(), {C.Name, Why});
  }

  void checkAgainstStart() {
    auto Start = std::find_if(Calls.begin(), Calls.end(), [](const Call &C) { return C.IsStart; });
    if (Start == Calls.end())
      return; // No run: nothing the registrations could change.
    for (auto C = Calls.begin(); C != Calls.end(); ++C) {
      if (C == Start)
        continue;
      if (C->IsStart) {
        reportCall(*C, "it is reached again here");
        continue;
      }
      if (C > Start) {
        reportCall(*C, "after the call to 'wash::start'");
        continue;
      }
      for (unsigned G : C->Guards)
        if (!std::binary_search(Start->Guards.begin(), Start->Guards.end(), G)) {
          reportCall(*C, Guards[G].What);
          break;
        }
    }
  }

  ASTContext &Ctx;
  ProgramIndex &Index;
  Diagnoser &D;
  std::vector<Guard> Guards{{0, ""}};
  std::vector<Frame> Frames;
  std::vector<Call> Calls;
  std::vector<Item> Work;
  CallWalk<unsigned> Walk; ///< The frames of the functions being walked.
};

} // namespace

bool checkRegistrationFlow(ProgramIndex &Index, Diagnoser &D, const FunctionDecl *Main) {
  FlowChecker(Index, D).run(Main);
  return !D.hasErrors();
}

} // namespace wash::tr
