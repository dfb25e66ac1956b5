/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2

import org.rsaml.analysis.plan.PlannedModule
import org.rsaml.analysis.plan.PlannedPort
import org.rsaml.generator.internal.cxx.CxxNames

/**
 * What a managed module's node (rclcpp_lifecycle, on rsaml/lifecycle.hpp) has beyond a plain
 * node's, in its base class gen/LAYER/ModuleBase.hpp (Ros2NodeTemplate writes the rest): created
 * unconfigured with its releases and ports registered; its transitions, which create and release
 * the publishers, subscriptions and timers Ros2NodeTemplate writes; and the guard that keeps it from
 * publishing or reacting while it is not active.
 */
class Ros2ManagedNodeTemplate extends Ros2Template {

	val extension CxxNames names
	val extension Ros2Names rosNames
	val Ros2NodeTemplate node

	new(Ros2Context context, Ros2NodeTemplate node) {
		super(context)
		this.names = context.names
		this.rosNames = context.rosNames
		this.node = node
	}

	/** In the constructor: the releases and the ports registered; publishers, subscriptions and timers come later. */
	def construction(PlannedModule m) '''
		// Created unconfigured: publishers and subscriptions come with configure, timers with activate.
		«FOR r : m.releases»
			«r.timerMember»_release_ = this->rsaml_add_release(
			    «str(r.label)», «r.rank», «IF r.policy == org.rsaml.model.SchedulingPolicy.RR»true«ELSE»false«ENDIF», «r.deadlineNs», «r.costNs», «r.timerMember»_period_,
			    «context.bounds.of(r).responseNs», «IF r.edf»true«ELSE»false«ENDIF»);
		«ENDFOR»
		«FOR p : m.inputs»
			«p.subName»_port_ = this->rsaml_add_arrivals(«str(p.name)»);
		«ENDFOR»
		«FOR l : context.linksOf(m)»
			link_«l.stem»_port_ = this->rsaml_add_arrivals(«str(l.qualifiedName)»);
		«ENDFOR»
	'''

	/** The indices of its releases and ports in the schedule, for the timers and subscriptions created later. */
	def members(PlannedModule m) '''
		«FOR r : m.releases»
			std::size_t «r.timerMember»_release_;
		«ENDFOR»
		«FOR p : m.inputs»
			std::size_t «p.subName»_port_;
		«ENDFOR»
		«FOR l : context.linksOf(m)»
			std::size_t link_«l.stem»_port_;
		«ENDFOR»
		«IF !m.outputs.empty»
			// held while a send marks its port (markSent) and while on_deactivate forgets the marks
			std::mutex sending_;
		«ENDIF»
	'''

	/**
	 * In a send method: marks the port sent, or returns when the node is not active. Under the lock on_deactivate
	 * forgets the marks under once the node is no longer active, so that no mark set by a send that found the node
	 * active outlives a deactivation, whatever thread sends (a release's, the data arrivals').
	 */
	def markSent(PlannedPort p) '''
		{
		  std::lock_guard<std::mutex> lock(sending_);
		  «inactiveReturn»
		  «p.sentName»_ = true;
		}
	'''

	/** A managed node drops what arrives while it is not active. */
	def inactiveReturn() '''
		if (!this->rsaml_active()) {
		  return;  // not active
		}
	'''

	/** The transitions of a managed node. */
	def transitions(PlannedModule m) '''
		  // The transitions of the managed node; an override of yours calls these.
		  CallbackReturn on_configure(const rclcpp_lifecycle::State& state) override {
		    (void)state;
		    «node.entities(m)»
		    this->rsaml_state(false, "inactive");
		    return CallbackReturn::SUCCESS;
		  }

		  CallbackReturn on_activate(const rclcpp_lifecycle::State& state) override {
		    (void)state;
		    «FOR p : m.outputs»
		    	«p.pubName»_->on_activate();
		    «ENDFOR»
		    «node.timers(m)»
		    this->rsaml_state(true, "active");
		    return CallbackReturn::SUCCESS;
		  }

		  CallbackReturn on_deactivate(const rclcpp_lifecycle::State& state) override {
		    (void)state;
		    «IF m.outputs.empty»
		    	this->rsaml_state(false, "inactive");
		    «ELSE»
		    	{
		    	  // A send that no publish of the ports has followed yet is forgotten (a periodic node's input handler sends
		    	  // and its next release's publish skips the port): the first publish after activation publishes every port.
		    	  std::lock_guard<std::mutex> lock(sending_);
		    	  this->rsaml_state(false, "inactive");
		    	  «FOR p : m.outputs»
		    	  	«p.sentName»_ = false;
		    	  «ENDFOR»
		    	}
		    «ENDIF»
		    rsaml_stop_timers();
		    «FOR p : m.outputs»
		    	«p.pubName»_->on_deactivate();
		    «ENDFOR»
		    return CallbackReturn::SUCCESS;
		  }

		  CallbackReturn on_cleanup(const rclcpp_lifecycle::State& state) override {
		    (void)state;
		    rsaml_release_entities();
		    this->rsaml_state(false, "unconfigured");
		    return CallbackReturn::SUCCESS;
		  }

		  CallbackReturn on_shutdown(const rclcpp_lifecycle::State& state) override {
		    (void)state;
		    this->rsaml_state(false, "finalized");
		    rsaml_release_entities();
		    return CallbackReturn::SUCCESS;
		  }
	'''

	/** What a managed node releases when it is deactivated, cleaned up or shut down. */
	def releaseEntities(PlannedModule m) '''
		  void rsaml_stop_timers() {
		    «FOR r : m.releases»
		    	if («r.timerMember»_) {
		    	  «r.timerMember»_->cancel();
		    	  «r.timerMember»_.reset();
		    	}
		    «ENDFOR»
		  }

		  void rsaml_release_entities() {
		    rsaml_stop_timers();
		    «FOR p : m.outputs»
		    	«p.pubName»_.reset();
		    «ENDFOR»
		    «FOR p : m.inputs»
		    	«p.subName»_.reset();
		    «ENDFOR»
		    «FOR l : context.linksOf(m)»
		    	link_«l.stem»_sub_.reset();
		    	link_«l.stem»_until_.reset();
		    «ENDFOR»
		    «FOR f : m.stepFunctions.filter[minIntervalNs > 0]»
		    	«f.lastRunMember».reset();
		    «ENDFOR»
		    «IF m.reactive && m.reactionIntervalNs > 0»
		    	last_reaction_.reset();
		    «ENDIF»
		  }
	'''
}
